/**
 * Light sources: ambient, directional, point (a disk for soft shadows when it has a radius) and spot lights, and the
 * per-point {@link lighting.LightSample} they fill. Core: JDK only.
 */
package lighting;
