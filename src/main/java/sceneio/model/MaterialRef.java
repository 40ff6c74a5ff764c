package sceneio.model;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.SerializerProvider;
import com.fasterxml.jackson.databind.annotation.JsonDeserialize;
import com.fasterxml.jackson.databind.annotation.JsonSerialize;
import com.fasterxml.jackson.databind.deser.std.StdDeserializer;
import com.fasterxml.jackson.databind.ser.std.StdSerializer;
import java.io.IOException;

/**
 * A geometry's material: the name of an entry in the scene's {@code materials} (reused by many geometries), or a
 * material object written in place. Exactly one of {@code name} and {@code inline} is set.
 */
@JsonSerialize(using = MaterialRef.Serializer.class)
@JsonDeserialize(using = MaterialRef.Deserializer.class)
public record MaterialRef(String name, MaterialDocument inline) {
    /**
     * Checks that exactly one of the two components is set.
     *
     * @param name the name of an entry in the scene's {@code materials}, or null for an inline material
     * @param inline the material written in place, or null for a named material
     * @throws IllegalArgumentException if both or neither of {@code name} and {@code inline} are null
     */
    public MaterialRef {
        if ((name == null) == (inline == null)) {
            throw new IllegalArgumentException("a material reference is either a name or a material object");
        }
    }

    /**
     * A reference to a named entry of the scene's {@code materials}.
     *
     * @param name the material's name in {@code materials}; not null
     * @return a reference by name
     */
    public static MaterialRef named(String name) {
        return new MaterialRef(name, null);
    }

    /**
     * A material written in place.
     *
     * @param material the material document; not null
     * @return a reference holding the material itself
     */
    public static MaterialRef of(MaterialDocument material) {
        return new MaterialRef(null, material);
    }

    /** Writes the name as a string, or the material object. */
    static final class Serializer extends StdSerializer<MaterialRef> {
        Serializer() {
            super(MaterialRef.class);
        }

        @Override
        public void serialize(MaterialRef ref, JsonGenerator gen, SerializerProvider provider) throws IOException {
            if (ref.name != null) gen.writeString(ref.name);
            else provider.defaultSerializeValue(ref.inline, gen);
        }
    }

    /** Reads a string (a name) or an object (a material). */
    static final class Deserializer extends StdDeserializer<MaterialRef> {
        Deserializer() {
            super(MaterialRef.class);
        }

        @Override
        public MaterialRef deserialize(JsonParser p, DeserializationContext ctxt) throws IOException {
            JsonToken t = p.currentToken();
            if (t == JsonToken.VALUE_STRING) return named(p.getText());
            if (t == JsonToken.START_OBJECT) return of(ctxt.readValue(p, MaterialDocument.class));
            throw Vec3.mismatch(
                    p,
                    MaterialRef.class,
                    "expected a material: the name of an entry in \"materials\" (a string) or a material object,"
                            + " but found " + Vec3.describe(t));
        }
    }
}
