package sceneio.model;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.SerializerProvider;
import com.fasterxml.jackson.databind.annotation.JsonDeserialize;
import com.fasterxml.jackson.databind.annotation.JsonSerialize;
import com.fasterxml.jackson.databind.deser.std.StdDeserializer;
import com.fasterxml.jackson.databind.exc.MismatchedInputException;
import com.fasterxml.jackson.databind.ser.std.StdSerializer;
import java.io.IOException;

/**
 * Three numbers written as a JSON array {@code [x, y, z]}: a point, a direction or an RGB colour (0..255 linear,
 * values above 255 allowed for bright lights). Exactly three finite numbers are accepted.
 */
@JsonSerialize(using = Vec3.Serializer.class)
@JsonDeserialize(using = Vec3.Deserializer.class)
public record Vec3(double x, double y, double z) {
    /** Writes {@code [x, y, z]}, integral values without a decimal point so files stay readable. */
    static final class Serializer extends StdSerializer<Vec3> {
        Serializer() {
            super(Vec3.class);
        }

        @Override
        public void serialize(Vec3 v, JsonGenerator gen, SerializerProvider provider) throws IOException {
            gen.writeStartArray();
            writeNumber(gen, v.x);
            writeNumber(gen, v.y);
            writeNumber(gen, v.z);
            gen.writeEndArray();
        }
    }

    /** Reads {@code [x, y, z]}; anything else is a mismatch naming what is expected. */
    static final class Deserializer extends StdDeserializer<Vec3> {
        Deserializer() {
            super(Vec3.class);
        }

        @Override
        public Vec3 deserialize(JsonParser p, DeserializationContext ctxt) throws IOException {
            double[] values = readNumbers(p, 3, "[x, y, z]", Vec3.class);
            return new Vec3(values[0], values[1], values[2]);
        }
    }

    /** A number as an integer when that is exact and reads back identically, else as a double. */
    static void writeNumber(JsonGenerator gen, double value) throws IOException {
        if (value == Math.rint(value) && Math.abs(value) < 1e15 && !isNegativeZero(value)) {
            gen.writeNumber((long) value);
        } else {
            gen.writeNumber(value);
        }
    }

    private static boolean isNegativeZero(double value) {
        return value == 0 && Double.doubleToRawLongBits(value) != 0;
    }

    /** Reads an array of exactly {@code count} finite numbers at the parser's current token. */
    static double[] readNumbers(JsonParser p, int count, String shape, Class<?> type) throws IOException {
        if (p.currentToken() != JsonToken.START_ARRAY) {
            throw mismatch(
                    p,
                    type,
                    "expected " + shape + " (an array of " + count + " numbers), but found "
                            + describe(p.currentToken()));
        }
        double[] values = new double[count];
        int n = 0;
        for (JsonToken t = p.nextToken(); t != JsonToken.END_ARRAY; t = p.nextToken()) {
            if (t == null) throw mismatch(p, type, "unexpected end of input inside " + shape);
            if (!t.isNumeric()) {
                throw mismatch(
                        p,
                        type,
                        "expected " + shape + " (an array of " + count + " numbers), but element " + n + " is "
                                + describe(t));
            }
            if (n >= count) {
                throw mismatch(p, type, "expected " + shape + " (an array of " + count + " numbers), but it has more");
            }
            double value = p.getDoubleValue();
            if (!Double.isFinite(value)) {
                throw mismatch(
                        p, type, "element " + n + " of " + shape + " must be a finite number, but was " + p.getText());
            }
            values[n++] = value;
        }
        if (n != count) {
            throw mismatch(p, type, "expected " + shape + " (an array of " + count + " numbers), but it has " + n);
        }
        return values;
    }

    static MismatchedInputException mismatch(JsonParser p, Class<?> type, String message) {
        return MismatchedInputException.from(p, type, message);
    }

    /** A JSON token in words, for messages. */
    static String describe(JsonToken token) {
        if (token == null) return "the end of the input";
        return switch (token) {
            case START_OBJECT -> "an object";
            case START_ARRAY -> "an array";
            case VALUE_STRING -> "a string";
            case VALUE_NUMBER_INT, VALUE_NUMBER_FLOAT -> "a number";
            case VALUE_TRUE, VALUE_FALSE -> "a boolean";
            case VALUE_NULL -> "null";
            default -> token.asString() == null ? token.name() : "'" + token.asString() + "'";
        };
    }
}
