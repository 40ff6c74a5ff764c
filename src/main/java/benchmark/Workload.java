package benchmark;

import geometries.Intersectable;
import java.util.function.Supplier;
import primitives.Point;
import primitives.Vector;

/**
 * One row group of the BVH benchmark: a scene and the pinhole camera its coherent rays come from. Incoherent
 * rays start uniformly inside the scene's bounding box, so they need nothing more.
 *
 * @param name short label printed in the table
 * @param scene builds the scene (called once per build timing, so it must be deterministic)
 * @param eye camera position of the coherent rays
 * @param target point the camera looks at
 * @param up the camera's up direction
 */
public record Workload(String name, Supplier<Intersectable> scene, Point eye, Point target, Vector up) {}
