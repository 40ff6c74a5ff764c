package benchmark;

import geometries.BoundingBox;
import geometries.Intersectable;
import java.util.function.Supplier;
import primitives.Point;
import primitives.Vector;

/**
 * One row group of the BVH benchmark: a scene and the pinhole camera its coherent rays come from. Incoherent
 * rays start uniformly inside {@code rayBox}, by default the scene's bounding box (a scene with an unbounded
 * member, such as the street's ground plane, names the box of its bounded part).
 *
 * @param name short label printed in the table
 * @param scene builds the scene (called once per build timing, so it must be deterministic)
 * @param eye camera position of the coherent rays
 * @param target point the camera looks at
 * @param up the camera's up direction
 * @param rayBox where incoherent rays start; null for the scene's bounding box
 */
public record Workload(
        String name, Supplier<Intersectable> scene, Point eye, Point target, Vector up, BoundingBox rayBox) {
    /**
     * A workload whose incoherent rays start in the bounding box of its (bounded) scene.
     *
     * @param name the workload's name in the table and in {@code only=}
     * @param scene builds the scene to search
     * @param eye the position of the pinhole camera of the coherent rays
     * @param target the point the pinhole camera looks at
     * @param up the camera's approximate up direction
     */
    public Workload(String name, Supplier<Intersectable> scene, Point eye, Point target, Vector up) {
        this(name, scene, eye, target, up, null);
    }
}
