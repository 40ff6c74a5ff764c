package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.ReusableRay;
import primitives.Vector;

/**
 * Packets of shadow segments ({@link Accelerator#blockShadowPacket}) give the answers of one {@link
 * Accelerator#passesLight} query per segment, bit for bit: spheres (their own loop), a sphere subclass and cylinders
 * (one query per segment), a plane, nested lists, segments that start on a sphere or end inside one, and a surface
 * the segments leave, which both leave out.
 */
class ShadowPacketTest {
    static Stream<Arguments> seeds() {
        return LongStream.range(0, 6).mapToObj(i -> Arguments.of(0x5AC4L + 104_729L * i));
    }

    /** A sphere whose queries are its own: the packet must ask them, not the sphere's loop. */
    private static final class ShrunkSphere extends Sphere {
        ShrunkSphere(Point centre, double radius) {
            super(centre, radius);
        }

        @Override
        public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
            // Hits only where the ray's origin lies above the centre: not what Sphere's arithmetic says.
            return ray.oz() > getCenter().z && super.intersect(ray, tMin, tMax, hit);
        }
    }

    private static Geometries opaqueScene(Random random, Plane floor) {
        Geometries scene = new Geometries(floor);
        Geometries nested = new Geometries();
        for (int i = 0; i < 12; i++) {
            Point c = new Point(random.nextGaussian() * 2, random.nextGaussian() * 2, 1 + random.nextDouble() * 3);
            double r = 0.2 + random.nextDouble();
            Geometry g = switch (random.nextInt(4)) {
                case 0 -> new ShrunkSphere(c, r);
                case 1 ->
                    new Cylinder(r, new Ray(c, SurfaceStartProperty.randomUnit(random)), 0.5 + random.nextDouble());
                default -> new Sphere(c, r);
            };
            if (random.nextBoolean()) nested.add(g);
            else scene.add(g);
        }
        scene.add(nested);
        return scene;
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void packetsAnswerAsOneQueryPerSegment(long seed) {
        Random random = new Random(seed);
        Plane floor = new Plane(new Point(0, 0, 0), new Vector(0, 0, 1));
        Geometries scene = opaqueScene(random, floor);
        Accelerator brute = Accelerator.build(scene, false);
        assertTrue(brute.testsShadowPackets());
        ShadowPacket packet = new ShadowPacket();
        HitRecord scratch = new HitRecord(), single = new HitRecord();
        int blocked = 0, segments = 0;
        for (int p = 0; p < 400; p++) {
            // From the floor (left out, as a shading point's own flat surface) or from anywhere (nothing left out),
            // toward a disk-light-like cluster of ends, some of them inside or beyond the spheres.
            boolean fromFloor = p % 3 == 0;
            // Just below the floor now and then: the floor's query then finds it ahead, unless left out.
            double z = fromFloor ? (random.nextBoolean() ? 0 : -1e-9) : random.nextGaussian() * 3;
            Point from = new Point(random.nextGaussian() * 3, random.nextGaussian() * 3, z);
            Point light = new Point(random.nextGaussian() * 3, random.nextGaussian() * 3, 2 + random.nextDouble() * 4);
            Geometry leaving = fromFloor ? floor : null;
            scratch.leaveSurface(leaving, 0);
            single.leaveSurface(leaving, 0);
            packet.clear();
            int n = 1 + random.nextInt(40);
            double[][] segment = new double[n][];
            for (int i = 0; i < n; i++) {
                double vx = light.x + 0.5 * random.nextGaussian() - from.x;
                double vy = light.y + 0.5 * random.nextGaussian() - from.y;
                double vz = light.z + 0.5 * random.nextGaussian() - from.z;
                double tMax = Math.sqrt(vx * vx + vy * vy + vz * vz) * (random.nextInt(5) == 0 ? 0.3 : 1);
                segment[i] = new double[] {vx, vy, vz, tMax};
                packet.add(from.x, from.y, from.z, vx, vy, vz, tMax);
            }
            brute.blockShadowPacket(packet, scratch);
            assertEquals(n, packet.size());
            int open = 0;
            for (int i = 0; i < n; i++) if (!packet.blocked(i)) open++;
            assertEquals(open, packet.open(), "the count of open segments");
            for (int i = 0; i < n; i++) {
                Ray ray = new Ray(from, new Vector(segment[i][0], segment[i][1], segment[i][2]));
                single.occluderHint = -1;
                boolean passes = brute.passesLight(ray, 0, segment[i][3], single);
                assertEquals(!passes, packet.blocked(i), "seed " + seed + ", packet " + p + ", segment " + i);
                if (!passes) blocked++;
                segments++;
            }
        }
        // Both answers occur often enough for the comparison to mean something.
        assertTrue(blocked > segments / 10 && blocked < segments * 9 / 10, blocked + " of " + segments);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void segmentsFromASphereAnswerAsSingleQueries(long seed) {
        // Shadow rays from points on the sphere itself (offset as a renderer offsets them), toward both sides: the
        // roots near zero decide.
        Random random = new Random(seed);
        Sphere sphere = new Sphere(new Point(0.3, -0.2, 1), 0.5);
        Accelerator flat = Accelerator.build(new Geometries(sphere), true); // one bounded primitive: no tree
        assertTrue(flat.testsShadowPackets());
        ShadowPacket packet = new ShadowPacket();
        HitRecord scratch = new HitRecord(), single = new HitRecord();
        for (int p = 0; p < 300; p++) {
            Vector n = SurfaceStartProperty.randomUnit(random);
            Point on = sphere.getCenter().add(n.scale(0.5 * (1 + (random.nextInt(3) - 1) * 1e-15)));
            packet.clear();
            Vector[] d = new Vector[16];
            for (int i = 0; i < d.length; i++) {
                d[i] = SurfaceStartProperty.randomUnit(random);
                packet.add(on.x, on.y, on.z, d[i].x, d[i].y, d[i].z, 3);
            }
            flat.blockShadowPacket(packet, scratch);
            for (int i = 0; i < d.length; i++) {
                single.occluderHint = -1;
                assertEquals(!flat.passesLight(new Ray(on, d[i]), 0, 3, single), packet.blocked(i));
            }
        }
    }

    /** A primitive of a user's own with a packet loop through the public API: a slab {@code z in (1, 2)}. */
    private static final class Slab extends Geometry {
        @Override
        public Vector getNormal(Point point) {
            return Vector.AXIS_Z;
        }

        @Override
        public void completeHit(Ray ray, HitRecord hit) {
            throw new UnsupportedOperationException("only shadow queries here");
        }

        @Override
        public BoundingBox getBoundingBox() {
            return new BoundingBox(-100, -100, 1, 100, 100, 2);
        }

        @Override
        public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
            double t = (1.5 - ray.oz()) / ray.dz(); // the slab's mid-plane: any t crossing it is inside
            if (!(t > tMin && t < tMax)) return false;
            hit.t = t;
            hit.geometry = this;
            return true;
        }

        @Override
        public void blockAll(ShadowPacket packet, HitRecord scratch) {
            for (int i = 0; i < packet.size(); i++) {
                if (!packet.blocked(i) && intersect(packet.segment(i), 0, packet.end(i), scratch)) {
                    packet.block(i);
                    packet.block(i); // twice: still one segment fewer open
                }
            }
        }
    }

    @Test
    void aPrimitiveOfOnesOwnMarksSegmentsThroughThePublicApi() {
        Slab slab = new Slab();
        Accelerator brute = Accelerator.build(new Geometries(slab, new Sphere(new Point(5, 5, 5), 1)), false);
        assertTrue(brute.testsShadowPackets());
        ShadowPacket packet = new ShadowPacket();
        Random random = new Random(77);
        double[][] d = new double[30][];
        for (int i = 0; i < d.length; i++) {
            d[i] = new double[] {
                random.nextGaussian(), random.nextGaussian(), random.nextGaussian(), 1 + 3 * random.nextDouble()
            };
            packet.add(0, 0, 0, d[i][0], d[i][1], d[i][2], d[i][3]);
        }
        HitRecord scratch = new HitRecord(), single = new HitRecord();
        brute.blockShadowPacket(packet, scratch);
        int open = 0;
        for (int i = 0; i < d.length; i++) {
            boolean passes =
                    brute.passesLight(new Ray(Point.ZERO, new Vector(d[i][0], d[i][1], d[i][2])), 0, d[i][3], single);
            assertEquals(!passes, packet.blocked(i), "segment " + i);
            if (passes) open++;
        }
        assertEquals(open, packet.open());
        assertTrue(open > 0 && open < d.length, open + " of " + d.length + " open");
    }

    @Test
    void packetsApplyOnlyWithoutATreeTrianglesOrTransparency() {
        Sphere a = new Sphere(new Point(0, 0, 0), 1), b = new Sphere(new Point(3, 0, 0), 1);
        assertTrue(Accelerator.build(new Geometries(a, b), false).testsShadowPackets());
        Accelerator tree = Accelerator.build(new Geometries(a, b), true);
        assertFalse(tree.testsShadowPackets());
        IllegalStateException e = assertThrows(
                IllegalStateException.class, () -> tree.blockShadowPacket(new ShadowPacket(), new HitRecord()));
        assertTrue(e.getMessage().contains("passesLight"), e.getMessage());
        Triangle t = new Triangle(new Point(0, 0, 5), new Point(1, 0, 5), new Point(0, 1, 5));
        assertFalse(Accelerator.build(new Geometries(a, t), false).testsShadowPackets());
        Sphere glass = new Sphere(new Point(0, 3, 0), 1);
        glass.setMaterial(new Material().setKt(0.5));
        assertFalse(Accelerator.build(new Geometries(a, glass), false).testsShadowPackets());
    }

    @Test
    void aPacketRefusesWhatASingleRayRefuses() {
        ShadowPacket packet = new ShadowPacket();
        assertThrows(IllegalArgumentException.class, () -> packet.add(0, 0, 0, 0, 0, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> packet.add(Double.NaN, 0, 0, 1, 0, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> packet.add(0, 0, 0, 1, Double.POSITIVE_INFINITY, 0, 1));
        assertEquals(0, packet.size());
        // Finite coordinates whose sum overflows are an origin like any other.
        packet.add(Double.MAX_VALUE, Double.MAX_VALUE, 0, 1, 0, 0, 1);
        assertEquals(1, packet.size());
    }

    /**
     * A packet keeps each segment's unit direction as a single shadow ray computes it, bit for bit: ordinary
     * directions by the ray's factor, and the rare ones (tiny, huge, along an axis, signed zeros) as the ray
     * normalizes them.
     */
    @ParameterizedTest
    @MethodSource("seeds")
    void aPacketNormalizesEveryDirectionAsASingleRay(long seed) {
        Random random = new Random(seed);
        ShadowPacket packet = new ShadowPacket();
        ReusableRay single = new ReusableRay();
        double[] scales = {1, 1e-3, 1e3, 0x1p-520, 0x1p-499, 0x1p499, 0x1p520, Double.MIN_VALUE, 1e300};
        for (int i = 0; i < 400; i++) {
            double scale = scales[random.nextInt(scales.length)];
            double vx = random.nextGaussian() * scale, vy = random.nextGaussian() * scale;
            double vz = random.nextGaussian() * scale;
            switch (random.nextInt(6)) {
                case 0 -> vx = vy = 0;
                case 1 -> vy = -0.0;
                case 2 -> vz = 0;
                default -> {}
            }
            if (vx == 0 && vy == 0 && vz == 0) vz = -scale;
            packet.clear();
            packet.add(1e6 * random.nextGaussian(), random.nextGaussian(), 0, vx, vy, vz, 1);
            single.set(0, 0, 0, vx, vy, vz);
            String what = "(" + vx + ", " + vy + ", " + vz + ")";
            assertEquals(Double.doubleToRawLongBits(single.dx()), Double.doubleToRawLongBits(packet.dx[0]), what);
            assertEquals(Double.doubleToRawLongBits(single.dy()), Double.doubleToRawLongBits(packet.dy[0]), what);
            assertEquals(Double.doubleToRawLongBits(single.dz()), Double.doubleToRawLongBits(packet.dz[0]), what);
        }
    }
}
