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
