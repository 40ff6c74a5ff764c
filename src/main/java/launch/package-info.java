/**
 * How to run this program again in a JVM of its own: the render daemon's start, and the benchmarks that time a fresh
 * JVM. Tool: JDK only.
 */
package launch;
