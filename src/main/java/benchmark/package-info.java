/**
 * Benchmarks: the BVH kernel (BvhBenchmark), real renders (RenderBenchmark), effect planning, and their workloads.
 * Tool.
 */
package benchmark;
