/**
 * The robustness report's probes: acne, light leaks, thin gaps, precision at distance and under translation, against
 * a fixed-offset baseline (docs/ROBUSTNESS.md). Tool.
 */
package robustness;
