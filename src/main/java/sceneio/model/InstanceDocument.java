package sceneio.model;

import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;

/**
 * A placement of a prototype (from the scene's {@code prototypes}) without copying its geometry: scaled, then
 * rotated, then translated, or placed by an explicit matrix.
 *
 * @param of the prototype's name (required)
 * @param scale one number, or one per axis; non-zero (default 1)
 * @param rotate a rotation about an axis through the origin (default none)
 * @param translate offset added last (default [0, 0, 0])
 * @param matrix instead of scale, rotate and translate: 12 numbers, the rows of a 3 x 4 affine matrix
 */
@JsonPropertyOrder({"of", "scale", "rotate", "translate", "matrix"})
public record InstanceDocument(
        String of, Coefficient scale, RotationDocument rotate, Vec3 translate, List<Double> matrix)
        implements GeometryDocument {}
