package sceneio;

import java.util.List;
import java.util.function.BiFunction;
import primitives.Transform;
import primitives.Vector;
import sceneio.model.Coefficient;
import sceneio.model.InstanceDocument;
import sceneio.model.RotationDocument;
import sceneio.model.Vec3;

/**
 * Reads and writes the placement of an {@code instance} in a scene file: {@code scale}, {@code rotate} and
 * {@code translate} (applied in that order), or a 3 x 4 {@code matrix} instead of them.
 */
final class InstanceTransforms {
    private InstanceTransforms() {}

    /** The transform an instance document describes; problems are reported through {@code fail} at their field. */
    static Transform read(JsonPath at, InstanceDocument d, BiFunction<JsonPath, String, SceneFileException> fail)
            throws SceneFileException {
        if (d.matrix() != null) {
            if (d.scale() != null || d.rotate() != null || d.translate() != null) {
                throw fail.apply(
                        at.field("matrix"),
                        "give either \"matrix\" or \"scale\", \"rotate\" and \"translate\", not both");
            }
            List<Double> m = d.matrix();
            if (m.size() != 12 || m.contains(null)) {
                throw fail.apply(
                        at.field("matrix"),
                        "a matrix is 12 numbers (3 rows of 4: the linear part and the translation), but " + m.size()
                                + " values were given" + (m.contains(null) ? ", some null" : ""));
            }
            double[] values = new double[12];
            for (int i = 0; i < 12; i++) values[i] = m.get(i);
            return transform(at.field("matrix"), fail, () -> Transform.ofMatrix(values));
        }
        Transform t = Transform.IDENTITY;
        Coefficient s = d.scale();
        if (s != null) t = transform(at.field("scale"), fail, () -> Transform.scale(s.r(), s.g(), s.b()));
        RotationDocument r = d.rotate();
        if (r != null) {
            if (r.axis() == null || r.degrees() == null) {
                throw fail.apply(
                        at.field("rotate"),
                        "a rotation needs \"axis\" (a non-zero direction) and \"degrees\", e.g. {\"axis\": [0, 0, 1],"
                                + " \"degrees\": 90}");
            }
            Vec3 a = r.axis();
            Transform scaled = t;
            t = transform(
                    at.field("rotate"),
                    fail,
                    () -> scaled.then(Transform.rotate(new Vector(a.x(), a.y(), a.z()), r.degrees())));
        }
        Vec3 o = d.translate();
        if (o != null) {
            Transform turned = t;
            t = transform(at.field("translate"), fail, () -> turned.then(Transform.translate(o.x(), o.y(), o.z())));
        }
        return t;
    }

    /** The document of a placement: {@code translate} alone when the transform only moves, else the matrix. */
    static InstanceDocument write(String prototype, Transform t) {
        double[] m = t.toMatrix();
        if (t.isTranslation()) return new InstanceDocument(prototype, null, null, new Vec3(m[3], m[7], m[11]), null);
        List<Double> matrix = new java.util.ArrayList<>(12);
        for (double v : m) matrix.add(v);
        return new InstanceDocument(prototype, null, null, null, matrix);
    }

    @FunctionalInterface
    private interface Construction {
        Transform get();
    }

    private static Transform transform(
            JsonPath at, BiFunction<JsonPath, String, SceneFileException> fail, Construction construction)
            throws SceneFileException {
        try {
            return construction.get();
        } catch (IllegalArgumentException e) {
            throw fail.apply(at, e.getMessage());
        }
    }
}
