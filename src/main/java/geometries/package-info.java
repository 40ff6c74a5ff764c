/**
 * Shapes (Sphere, Plane, Polygon, Triangle, Cylinder, Tube, Mesh), their groups (Geometries), and the compiled
 * scene the renderer queries: {@link geometries.Accelerator} with its 8-wide {@link geometries.BVH}, the
 * watertight triangle test, the box-test kernels, and the shadow beams through which neighbouring shadow rays toward
 * one light share a search of the tree. Core: JDK only (the vectorized kernel uses the incubating Vector API when
 * the JVM has it).
 */
package geometries;
