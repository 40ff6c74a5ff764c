package report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The accuracy report on a tiny run, so the command never rots; and its numerical helpers. */
class AccuracyReportTest {

    @Test
    void aTinyRunWritesEveryOutputAndErrorsFallWithSamples(@TempDir Path out) throws IOException {
        AccuracyReport.Options options = new AccuracyReport.Options(
                24, 18, new int[] {1, 16}, 1, out, List.of(new AntiAliasingExperiment(), new SoftShadowExperiment()));
        List<Measurement> all = AccuracyReport.run(options, new PrintStream(new ByteArrayOutputStream()));
        assertEquals(2 * 5 * 2, all.size(), "2 experiments x 5 variants x 2 counts");
        for (String slug : List.of("aa", "shadows")) {
            assertTrue(Files.size(out.resolve("accuracy-" + slug + ".png")) > 1000, slug + " chart");
            assertTrue(Files.size(out.resolve("accuracy-" + slug + "-crops.png")) > 100, slug + " crops");
            List<String> csv = Files.readAllLines(out.resolve("accuracy").resolve(slug + ".csv"));
            assertEquals(Measurement.CSV_HEADER, csv.get(0));
            assertEquals(1 + 5 * 2, csv.size());
        }
        String report = Files.readString(out.resolve("accuracy").resolve("report.md"));
        assertTrue(report.contains("## anti-aliasing") && report.contains("## soft shadows"), report);
        // Each reference's own error, estimated from a second reference: above zero (a seed changes jittered samples).
        java.util.regex.Matcher own =
                java.util.regex.Pattern.compile("its own RMSE about ([0-9.]+)").matcher(report);
        for (int section = 0; section < 2; section++) {
            assertTrue(own.find(), "the reference's own error in each section");
            assertTrue(Double.parseDouble(own.group(1)) > 0, own.group());
        }
        assertTrue(report.contains("| less the reference's own |"), "the progressive table's column");
        for (Measurement m : all) {
            assertTrue(m.seconds() > 0 && m.rmse() >= 0 && m.p99() >= 0, m.toString());
            if (m.samples() == 16 && m.variant().equals("jittered")) {
                double oneSample = all.stream()
                        .filter(o -> o.experiment().equals(m.experiment())
                                && o.variant().equals("jittered")
                                && o.samples() == 1)
                        .findFirst()
                        .orElseThrow()
                        .rmse();
                assertTrue(
                        m.rmse() < oneSample, m.experiment() + ": 16 samples beat 1: " + m.rmse() + " vs " + oneSample);
            }
        }
        // Camera rays: one per pixel and sample for anti-aliasing, one per pixel for the shadow experiment.
        Measurement aa16 = all.stream()
                .filter(m -> m.experiment().equals("aa") && m.variant().equals("grid") && m.samples() == 16)
                .findFirst()
                .orElseThrow();
        assertEquals(24L * 18 * 16, aa16.cameraRays());
    }

    @Test
    void slopesOfExactPowerLawsAreRecovered() {
        double[] x = {4, 16, 64, 256};
        double[] y = new double[4];
        for (int i = 0; i < 4; i++) y[i] = 7 * Math.pow(x[i], -0.5);
        ConvergenceFit fit = ConvergenceFit.of(x, y);
        assertEquals(-0.5, fit.slope(), 1e-12);
        assertEquals(Math.log10(7), fit.intercept(), 1e-12);
        assertEquals(4, fit.factorToHalveError(), 1e-9, "random sampling: 4x the samples halve the error");
        assertEquals(
                Double.POSITIVE_INFINITY,
                ConvergenceFit.of(x, new double[] {1, 1, 1, 1}).factorToHalveError());
        assertTrue(Double.isNaN(
                ConvergenceFit.of(new double[] {1}, new double[] {1}).slope()));
    }

    @Test
    void imageErrorOfIdenticalImagesIsZeroAndOfAUniformShiftIsTheShift() {
        renderer.ImageWriter a = new renderer.ImageWriter("a", 10, 10), b = new renderer.ImageWriter("b", 10, 10);
        for (int y = 0; y < 10; y++) {
            for (int x = 0; x < 10; x++) {
                a.writePixel(x, y, new primitives.Color(100, 100, 100));
                b.writePixel(x, y, new primitives.Color(103, 103, 103));
            }
        }
        assertEquals(new ImageError(0, 0), ImageError.between(a, a));
        ImageError e = ImageError.between(a, b);
        assertEquals(3, e.rmse(), 1e-12);
        assertEquals(3, e.p99(), 1e-12);
    }

    @Test
    void badOptionsAreRejectedWithTheAllowedOnes() {
        IllegalArgumentException e = assertThrows(
                IllegalArgumentException.class, () -> AccuracyReport.parse(new String[] {"--sise", "8x8"}));
        assertTrue(e.getMessage().contains("--size"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> AccuracyReport.parse(new String[] {"--counts", "4"}));
    }
}
