package sceneio.model;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.SerializerProvider;
import com.fasterxml.jackson.databind.annotation.JsonDeserialize;
import com.fasterxml.jackson.databind.annotation.JsonSerialize;
import com.fasterxml.jackson.databind.deser.std.StdDeserializer;
import com.fasterxml.jackson.databind.ser.std.StdSerializer;
import java.io.IOException;

/**
 * A material or ambient coefficient: one number for all three colour channels ({@code 0.5}) or one per channel
 * ({@code [0.8, 0.2, 0.2]}). Written back as a single number when the channels are equal.
 */
@JsonSerialize(using = Coefficient.Serializer.class)
@JsonDeserialize(using = Coefficient.Deserializer.class)
public record Coefficient(double r, double g, double b) {
    /**
     * The same value in every channel.
     *
     * @param value the coefficient of all three channels
     * @return a uniform coefficient with {@code value} in the red, green and blue channels
     */
    public static Coefficient of(double value) {
        return new Coefficient(value, value, value);
    }

    /**
     * Whether the three channels are equal (compared as by {@link Double#compare}), so the coefficient is written as
     * one number.
     *
     * @return true when red, green and blue are the same value
     */
    public boolean isUniform() {
        return Double.compare(r, g) == 0 && Double.compare(g, b) == 0;
    }

    /** Writes one number when uniform, else {@code [r, g, b]}. */
    static final class Serializer extends StdSerializer<Coefficient> {
        Serializer() {
            super(Coefficient.class);
        }

        @Override
        public void serialize(Coefficient c, JsonGenerator gen, SerializerProvider provider) throws IOException {
            if (c.isUniform()) {
                Vec3.writeNumber(gen, c.r);
                return;
            }
            gen.writeStartArray();
            Vec3.writeNumber(gen, c.r);
            Vec3.writeNumber(gen, c.g);
            Vec3.writeNumber(gen, c.b);
            gen.writeEndArray();
        }
    }

    /** Reads a number or {@code [r, g, b]}. */
    static final class Deserializer extends StdDeserializer<Coefficient> {
        Deserializer() {
            super(Coefficient.class);
        }

        @Override
        public Coefficient deserialize(JsonParser p, DeserializationContext ctxt) throws IOException {
            if (p.currentToken() != null && p.currentToken().isNumeric()) {
                double value = p.getDoubleValue();
                if (!Double.isFinite(value)) {
                    throw Vec3.mismatch(
                            p, Coefficient.class, "coefficient must be a finite number, but was " + p.getText());
                }
                return of(value);
            }
            if (p.currentToken() != com.fasterxml.jackson.core.JsonToken.START_ARRAY) {
                throw Vec3.mismatch(
                        p,
                        Coefficient.class,
                        "expected a coefficient: a number or [r, g, b], but found " + Vec3.describe(p.currentToken()));
            }
            double[] v = Vec3.readNumbers(p, 3, "[r, g, b]", Coefficient.class);
            return new Coefficient(v[0], v[1], v[2]);
        }
    }
}
