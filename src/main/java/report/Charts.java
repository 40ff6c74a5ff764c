package report;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** Log-log convergence charts of an experiment, drawn with XChart. */
final class Charts {
    private Charts() {}

    /** Error against samples and against seconds, one series per variant, side by side in one picture. */
    static BufferedImage convergence(String title, String sampleUnit, Map<String, List<Measurement>> byVariant) {
        XYChart samples = chart(title + ": RMSE vs samples", sampleUnit, "RMSE (of 255)");
        XYChart time = chart(title + ": RMSE vs render time", "seconds", "RMSE (of 255)");
        for (Map.Entry<String, List<Measurement>> e : byVariant.entrySet()) {
            List<Measurement> m = e.getValue();
            double[] n = m.stream().mapToDouble(Measurement::samples).toArray();
            double[] s = m.stream().mapToDouble(Measurement::seconds).toArray();
            double[] err = m.stream().mapToDouble(Measurement::rmse).toArray();
            ConvergenceFit fit = ConvergenceFit.of(withoutFirst(n), withoutFirst(err));
            String label = String.format(java.util.Locale.ROOT, "%s (slope %.2f)", e.getKey(), fit.slope());
            XYSeries a = samples.addSeries(label, n, err);
            a.setMarker(SeriesMarkers.CIRCLE);
            XYSeries b = time.addSeries(e.getKey(), s, err);
            b.setMarker(SeriesMarkers.CIRCLE);
        }
        BufferedImage left = BitmapEncoder.getBufferedImage(samples);
        BufferedImage right = BitmapEncoder.getBufferedImage(time);
        BufferedImage both =
                new BufferedImage(left.getWidth() + right.getWidth(), left.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = both.createGraphics();
        g.drawImage(left, 0, 0, null);
        g.drawImage(right, left.getWidth(), 0, null);
        g.dispose();
        return both;
    }

    /**
     * The error each progressive render predicted against the error measured less the reference's own (what the
     * prediction estimates), one series per experiment, with the line where they are equal: points below it predicted
     * too little. A render whose measured error is all the reference's is left out (the axes are logarithmic).
     */
    static BufferedImage predictedVersusMeasured(List<ProgressiveCheck.Row> rows) {
        XYChart chart = chart(
                "Progressive sampling: predicted vs measured RMSE",
                "measured RMSE less the reference's own (of 255)",
                "predicted RMSE (of 255)");
        double lo = Double.POSITIVE_INFINITY, hi = 0;
        Map<String, List<ProgressiveCheck.Row>> byExperiment = new java.util.LinkedHashMap<>();
        for (ProgressiveCheck.Row r : rows) {
            if (!(r.measuredLessReference() > 0)) continue;
            byExperiment
                    .computeIfAbsent(r.experiment(), k -> new java.util.ArrayList<>())
                    .add(r);
            lo = Math.min(lo, Math.min(r.measuredLessReference(), r.predicted()));
            hi = Math.max(hi, Math.max(r.measuredLessReference(), r.predicted()));
        }
        for (Map.Entry<String, List<ProgressiveCheck.Row>> e : byExperiment.entrySet()) {
            double[] measured = e.getValue().stream()
                    .mapToDouble(ProgressiveCheck.Row::measuredLessReference)
                    .toArray();
            double[] predicted = e.getValue().stream()
                    .mapToDouble(ProgressiveCheck.Row::predicted)
                    .toArray();
            XYSeries series = chart.addSeries(e.getKey(), measured, predicted);
            series.setMarker(SeriesMarkers.CIRCLE);
            series.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        }
        XYSeries equal = chart.addSeries("predicted = measured", new double[] {lo, hi}, new double[] {lo, hi});
        equal.setMarker(SeriesMarkers.NONE);
        equal.setLineColor(Color.GRAY);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        return BitmapEncoder.getBufferedImage(chart);
    }

    /** The fit skips the one-sample point: every pattern puts a single sample at the centre. */
    private static double[] withoutFirst(double[] values) {
        return values.length > 1 ? java.util.Arrays.copyOfRange(values, 1, values.length) : values;
    }

    private static XYChart chart(String title, String x, String y) {
        XYChart chart = new XYChartBuilder()
                .width(560)
                .height(380)
                .title(title)
                .xAxisTitle(x)
                .yAxisTitle(y)
                .build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNE);
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.getStyler()
                .setChartTitleFont(chart.getStyler().getChartTitleFont().deriveFont(13f));
        return chart;
    }
}
