/**
 * Rendering on Apache Spark: tiles and animation frames as Spark tasks, bit-identical to a local render
 * (docs/SPARK.md; profile -Pspark).
 */
package distributed;
