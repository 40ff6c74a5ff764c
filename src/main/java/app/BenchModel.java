package app;

import geometries.Geometries;
import geometries.Mesh;
import primitives.Double3;
import primitives.Material;
import primitives.Point;

/**
 * A park bench as two indexed {@link Mesh}es of boxes: wooden slats (seat and backrest) and iron legs and arm
 * rests. Its length runs along y; it faces +x or -x (the way a sitter looks). The gaps between the slats cast
 * striped shadows, whose edges soft lamps blur. Units of the street (1 = 5 cm): 36 long, 17 high.
 */
final class BenchModel {
    static final double LENGTH = 36;

    private BenchModel() {}

    /** The bench with the middle of its front edge at {@code front} (z = the ground it stands on). */
    static Geometries build(Point front, int facing) {
        MeshBuilder wood = new MeshBuilder(), iron = new MeshBuilder();
        double x = front.x, y0 = front.y - LENGTH / 2, y1 = front.y + LENGTH / 2, z = front.z;
        // Depth coordinate d runs from the front edge (0) backward (against the facing direction).
        for (int k = 0; k < 3; k++) {
            double d0 = k * 3.1, d1 = d0 + 2.5;
            box(wood, x, facing, d0, d1, y0, y1, z + 8.6, z + 9.4);
        }
        for (int k = 0; k < 2; k++) {
            double h0 = z + 11 + 3.2 * k;
            box(wood, x, facing, 9.0, 9.7, y0, y1, h0, h0 + 2.4);
        }
        for (double yl : new double[] {y0 + 2, y1 - 3}) {
            box(iron, x, facing, 0.6, 1.6, yl, yl + 1, z, z + 8.6);
            box(iron, x, facing, 7.6, 8.6, yl, yl + 1, z, z + 8.6);
            box(iron, x, facing, 9.7, 10.6, yl, yl + 1, z, z + 17);
            box(iron, x, facing, 0, 9.7, yl, yl + 1, z + 12.5, z + 13.3);
        }
        Double3 woodColour = new Double3(0.45, 0.28, 0.14);
        return new Geometries(
                wood.build()
                        .setMaterial(new Material()
                                .setKd(woodColour)
                                .setKa(woodColour)
                                .setKs(0.15)
                                .setShininess(20)),
                iron.build()
                        .setMaterial(new Material()
                                .setKd(0.08)
                                .setKa(0.08)
                                .setKs(0.5)
                                .setShininess(60)));
    }

    /** A box spanning depth d0..d1 behind the front line x (against {@code facing}), y0..y1 and z0..z1. */
    private static void box(
            MeshBuilder mesh, double x, int facing, double d0, double d1, double y0, double y1, double z0, double z1) {
        double xa = x - facing * d0, xb = x - facing * d1;
        mesh.box(Math.min(xa, xb), y0, z0, Math.max(xa, xb), y1, z1);
    }
}
