package geometries;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** What the C twin reads is what the kernel reads: the export's files hold the kernel's arrays and answers. */
class KernelTwinExportTest {
    @Test
    void theExportHoldsTheKernelsArraysAndAnswers(@TempDir Path dir) throws IOException {
        Accelerator accelerator = Accelerator.build(Meshes.heightfield(40), true);
        Ray[] coherent = {
            new Ray(new Point(0.1, 0.05, 2), new Vector(0, 0, -1)), new Ray(new Point(5, 5, 5), new Vector(1, 1, 1))
        };
        Ray[] incoherent = {new Ray(new Point(0.2, -0.3, 1), new Vector(0.1, 0.2, -1))};
        KernelTwinExport.export(
                accelerator, new Ray[][] {coherent, incoherent}, new String[] {"coherent", "incoherent"}, dir);

        ByteBuffer header = read(dir.resolve("header"));
        int[] layout = new int[KernelTwinExport.LAYOUT.length];
        for (int i = 0; i < layout.length; i++) layout[i] = header.getInt();
        assertArrayEquals(KernelTwinExport.LAYOUT, layout);
        BVH bvh = accelerator.getBvh();
        CompiledPrimitives primitives = accelerator.compiledPrimitives();
        assertEquals(bvh.rootLink, header.getInt());
        assertEquals(bvh.rootCount, header.getInt());
        assertEquals(bvh.nodes.length, header.getInt());
        assertEquals(primitives.triangles.length, header.getInt());
        assertEquals(primitives.info.length, header.getInt());
        assertEquals(2, header.getInt());
        assertEquals(1, header.getInt());

        ByteBuffer nodes = read(dir.resolve("nodes"));
        float[] exportedNodes = new float[bvh.nodes.length];
        for (int i = 0; i < exportedNodes.length; i++) exportedNodes[i] = nodes.getFloat();
        assertArrayEquals(bvh.nodes, exportedNodes);
        ByteBuffer triangles = read(dir.resolve("triangles"));
        assertEquals(Double.doubleToRawLongBits(primitives.triangles[7]), triangles.getLong(8 * 7));
        assertEquals(8 * primitives.triangles.length, triangles.capacity());

        // The first ray hits the heightfield from above, the second points away from it: one distance, one -1.
        ByteBuffer distances = read(dir.resolve("coherent.t"));
        HitRecord hit = new HitRecord();
        assertTrue(accelerator.intersect(coherent[0], 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(hit.t, distances.getDouble(0));
        assertEquals(-1, distances.getDouble(8));
        ByteBuffer rays = read(dir.resolve("incoherent"));
        assertEquals(incoherent[0].dz(), rays.getDouble(40));
    }

    @Test
    void onlyATreeOfTrianglesIsExported() {
        assertTrue(KernelTwinExport.onlyTriangles(
                Accelerator.build(Meshes.heightfield(8), true).compiledPrimitives()));
        Geometries withSphere = new Geometries(Meshes.heightfield(8), new Sphere(new Point(0, 0, 1), 0.1));
        assertFalse(KernelTwinExport.onlyTriangles(
                Accelerator.build(withSphere, true).compiledPrimitives()));
        Geometries withPlane =
                new Geometries(Meshes.heightfield(8), new Plane(new Point(0, 0, -1), new Vector(0, 0, 1)));
        assertFalse(KernelTwinExport.onlyTriangles(
                Accelerator.build(withPlane, true).compiledPrimitives()));
    }

    private static ByteBuffer read(Path file) throws IOException {
        return ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.LITTLE_ENDIAN);
    }
}
