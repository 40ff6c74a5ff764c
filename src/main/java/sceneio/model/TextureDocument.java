package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import primitives.Texture;

/**
 * An image texture: a PNG or JPEG file and what texture coordinates outside [0, 1] mean.
 *
 * @param file path of the image relative to the scene file's folder (required)
 * @param wrap {@code repeat} (default), {@code clamp} or {@code mirror}
 */
@JsonPropertyOrder({"file", "wrap"})
public record TextureDocument(String file, Texture.Wrap wrap) {}
