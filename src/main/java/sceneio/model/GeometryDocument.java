package sceneio.model;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

/**
 * A geometry in a scene file, told apart by its {@code "type"}. All but {@code group} and {@code instance} take an optional
 * {@code material} (a name from {@code materials} or a material object) and {@code emission} colour.
 */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, property = "type")
@JsonSubTypes({
    @JsonSubTypes.Type(value = SphereDocument.class, name = "sphere"),
    @JsonSubTypes.Type(value = PlaneDocument.class, name = "plane"),
    @JsonSubTypes.Type(value = TriangleDocument.class, name = "triangle"),
    @JsonSubTypes.Type(value = PolygonDocument.class, name = "polygon"),
    @JsonSubTypes.Type(value = TubeDocument.class, name = "tube"),
    @JsonSubTypes.Type(value = CylinderDocument.class, name = "cylinder"),
    @JsonSubTypes.Type(value = MeshDocument.class, name = "mesh"),
    @JsonSubTypes.Type(value = GroupDocument.class, name = "group"),
    @JsonSubTypes.Type(value = InstanceDocument.class, name = "instance")
})
public sealed interface GeometryDocument
        permits SphereDocument,
                PlaneDocument,
                TriangleDocument,
                PolygonDocument,
                TubeDocument,
                CylinderDocument,
                MeshDocument,
                GroupDocument,
                InstanceDocument {}
