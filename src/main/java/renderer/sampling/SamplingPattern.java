package renderer.sampling;

/** How sample points are placed over a target area. */
public enum SamplingPattern {
    /** A regular lattice of cell centres: no noise, but structured (aliasing) error. */
    GRID,
    /** One random point in each lattice cell (stratified): noise without clumping. */
    JITTERED,
    /** Independent uniform points: the textbook Monte Carlo baseline (error about n^-1/2). */
    RANDOM,
    /** The 2D Halton sequence (bases 2 and 3) with a random rotation per stream: low discrepancy. */
    HALTON
}
