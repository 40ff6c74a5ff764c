package sceneio.model;

import java.util.List;

/**
 * A nested composite of geometries (the core's {@code Geometries}), to keep related parts together.
 *
 * @param geometries its members (required, may be empty)
 */
public record GroupDocument(List<GeometryDocument> geometries) implements GeometryDocument {}
