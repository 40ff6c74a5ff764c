package sceneio.model;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

/** A light source in a scene file, told apart by its {@code "type"}: point, spot or directional. */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, property = "type")
@JsonSubTypes({
    @JsonSubTypes.Type(value = PointLightDocument.class, name = "point"),
    @JsonSubTypes.Type(value = SpotLightDocument.class, name = "spot"),
    @JsonSubTypes.Type(value = DirectionalLightDocument.class, name = "directional")
})
public sealed interface LightDocument permits PointLightDocument, SpotLightDocument, DirectionalLightDocument {}
