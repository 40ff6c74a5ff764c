/**
 * The value types the rest is written in: Point, Vector, Ray (and the render loop's ReusableRay), Color, Double3,
 * Material, and the shared numeric helpers and limits (Util, Limits). Core: JDK only.
 */
package primitives;
