package robustness;

import java.util.Locale;
import renderer.ImageWriter;

/**
 * Prints the robustness metrics as Markdown tables: self-intersection and thin-gap failures by shape and distance
 * (with the fixed-offset baseline beside them), hit-point precision far from the origin, translation invariance,
 * leaks through closed meshes, non-finite values, and agreement of the BVH with brute force.
 *
 * <p>Run: {@code mvn -q compile exec:java -Dexec.mainClass=robustness.RobustnessReport [-Dexec.args=probes]}.
 */
public final class RobustnessReport {
    private static final double[] DISTANCES = {1, 1e3, 1e6, 1e9};

    /** Fewest probes that give a rate worth printing, and most (500 times the default, some hours). */
    public static final int MIN_PROBES = 100, MAX_PROBES = 10_000_000;

    private RobustnessReport() {}

    /**
     * Runs every probe and prints the tables to standard output.
     *
     * @param args optionally the number of probes per table cell (default 20,000)
     */
    public static void main(String[] args) {
        int probes = args.length > 0 ? Integer.parseInt(args[0]) : 20_000;
        if (probes < MIN_PROBES || probes > MAX_PROBES) {
            throw new IllegalArgumentException(
                    "probes must be in [" + MIN_PROBES + ", " + MAX_PROBES + "], but was " + probes);
        }
        long seed = 20261122L;
        long nonFinite = 0, disagreements = 0;
        StringBuilder out = new StringBuilder();
        out.append(String.format(Locale.ROOT, "%d probes per cell, seed %d%n%n", probes, seed));

        out.append("### Self-intersection (acne): spawned rays that hit their own surface\n\n");
        out.append("| shape | distance 1 | 1e3 | 1e6 | 1e9 |\n|---|---:|---:|---:|---:|\n");
        for (AcneProbe.Shape shape : AcneProbe.Shape.values()) {
            out.append("| ").append(shape.name().toLowerCase(Locale.ROOT));
            for (double d : DISTANCES) {
                AcneProbe.Result r = AcneProbe.run(shape, d, probes, seed, true);
                if (!r.equals(AcneProbe.run(shape, d, probes, seed, false))) disagreements++;
                nonFinite += r.nonFinite();
                out.append(String.format(Locale.ROOT, " | %d / %,d", r.selfHits(), r.spawned()));
            }
            out.append(" |\n");
        }

        out.append("\n### Leaks: rays from inside a closed icosphere (level 3) aimed at its vertices and edges\n\n");
        out.append("| placement | rays | leaks (watertight, ours) | leaks (textbook Moller-Trumbore) |\n");
        out.append("|---|---:|---:|---:|\n");
        for (double offset : new double[] {0, 1e6}) {
            for (double scale : new double[] {1, 1e3}) {
                LeakProbe.Result r = LeakProbe.run(3, scale, offset, Math.max(2, probes / 2500), seed, true);
                if (!r.equals(LeakProbe.run(3, scale, offset, Math.max(2, probes / 2500), seed, false))) {
                    disagreements++;
                }
                out.append(String.format(
                        Locale.ROOT,
                        "| radius %.0e, %.0e from the origin | %,d | %d | %,d (%.1f%%) |%n",
                        scale,
                        offset,
                        r.rays(),
                        r.leaks(),
                        r.textbookLeaks(),
                        100.0 * r.textbookLeaks() / r.rays()));
            }
        }

        out.append("\n### Thin gaps: rays leaving a unit sphere that miss a concentric sphere 1e-6 larger\n\n");
        out.append("| spawning | distance 1 | 1e3 | 1e6 | 1e9 |\n|---|---:|---:|---:|---:|\n");
        out.append("| error-bounded offset (ours): escaped + self-hits");
        for (double d : DISTANCES) {
            ThinGapProbe.Result r = ThinGapProbe.run(d, 1e-6, probes, seed, true);
            if (!r.equals(ThinGapProbe.run(d, 1e-6, probes, seed, false))) disagreements++;
            out.append(String.format(Locale.ROOT, " | %d / %,d", r.failures(), r.spawned()));
        }
        out.append(" |\n");
        for (double delta : new double[] {0.1, 1e-9}) {
            StringBuilder escapes = new StringBuilder("| fixed offset " + delta + ": escaped");
            StringBuilder acne = new StringBuilder("| fixed offset " + delta + ": self-hits (acne)");
            for (double d : DISTANCES) {
                FixedOffsetBaseline.Result r = FixedOffsetBaseline.run(d, delta, 1e-6, probes, seed);
                escapes.append(String.format(Locale.ROOT, " | %d / %,d", r.escaped(), r.spawned()));
                acne.append(String.format(Locale.ROOT, " | %d / %,d", r.selfHits(), r.spawned()));
            }
            out.append(escapes).append(" |\n").append(acne).append(" |\n");
        }

        out.append(
                "\n### Precision at distance: hit-point distance from the exact surface, in ulps of the distance\n\n");
        out.append("| shape | statistic | 1e3 | 1e6 | 1e9 | 1e12 |\n|---|---|---:|---:|---:|---:|\n");
        double[] far = {1e3, 1e6, 1e9, 1e12};
        for (String shape : new String[] {"sphere", "triangle"}) {
            StringBuilder max = new StringBuilder("| " + shape + " | max");
            StringBuilder mean = new StringBuilder("| " + shape + " | mean");
            for (double d : far) {
                PrecisionProbe.Result r = shape.equals("sphere")
                        ? PrecisionProbe.sphere(d, probes / 4, seed)
                        : PrecisionProbe.triangle(d, probes / 4, seed);
                nonFinite += r.nonFinite();
                max.append(String.format(Locale.ROOT, " | %.2f", r.maxUlps()));
                mean.append(String.format(Locale.ROOT, " | %.2f", r.meanUlps()));
            }
            out.append(max).append(" |\n").append(mean).append(" |\n");
        }

        out.append("\n### Translation invariance: the test scene moved away from the origin (200 x 200)\n\n");
        out.append("| offset | pixels differing by more than 1/255 | RMS difference (of 255) | max difference |\n");
        out.append("|---:|---:|---:|---:|\n");
        ImageWriter reference = TranslationProbe.render(0, 200, true);
        nonFinite += TranslationProbe.compare(reference, 0, reference).nonFinitePixels();
        for (double offset : new double[] {1e3, 1e6, 1e9}) {
            ImageWriter image = TranslationProbe.render(offset, 200, true);
            TranslationProbe.Result r = TranslationProbe.compare(reference, offset, image);
            nonFinite += r.nonFinitePixels();
            if (TranslationProbe.compare(image, offset, TranslationProbe.render(offset, 200, false))
                            .max()
                    != 0) {
                disagreements++;
            }
            out.append(String.format(
                    Locale.ROOT,
                    "| %.0e | %.3f%% | %.2e | %.2e |%n",
                    offset,
                    100 * r.differingFraction(),
                    r.rms(),
                    r.max()));
        }

        out.append(
                String.format(Locale.ROOT, "%nNon-finite hit records and pixels over the whole run: %d%n", nonFinite));
        out.append(String.format(
                Locale.ROOT,
                "Cells where the BVH and brute force disagree (any count or any pixel): %d%n",
                disagreements));
        System.out.print(out);
    }
}
