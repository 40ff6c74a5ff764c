package geometries;

import primitives.Point;
import primitives.Ray;
import primitives.Transform;
import primitives.Util;
import primitives.Vector;

/**
 * An indexed triangle mesh: one shared vertex array and three vertex indices per triangle, optionally with
 * per-vertex normals for smooth shading and per-vertex texture coordinates for texture maps. In a compiled scene the BVH sees each triangle on its own.
 *
 * <p>All edges of a mesh are treated as shared (see {@link WatertightTriangle}): a ray through an edge or vertex
 * hits exactly one of the triangles around it, so closed meshes do not leak. Validation rejects NaN or infinite
 * coordinates and out-of-range or negative indices; triangles of zero area are kept (their indices are valid) but
 * never hit and never enter the BVH.
 */
public class Mesh extends Geometry {
    final double[] vertices;
    final int[] indices;
    private final double[] normals;
    /** u, v per vertex (OBJ {@code vt}), or null: then hits leave the texture coordinates at 0. */
    private final double[] texCoords;

    /**
     * @param vertices x, y, z of each vertex
     * @param indices three vertex indices per triangle
     */
    public Mesh(double[] vertices, int[] indices) {
        this(vertices, indices, null);
    }

    /**
     * @param normals x, y, z of a normal per vertex (need not be unit), or null for flat shading
     * @param vertices x, y, z of each vertex
     * @param indices three 0-based vertex indices per triangle, at least one triangle
     */
    public Mesh(double[] vertices, int[] indices, double[] normals) {
        this(vertices, indices, normals, null);
    }

    /**
     * @param vertices x, y, z of each vertex
     * @param indices three 0-based vertex indices per triangle, at least one triangle
     * @param normals x, y, z of a normal per vertex (need not be unit), or null for flat shading
     * @param texCoords u, v of texture coordinates per vertex (finite), or null for none
     */
    public Mesh(double[] vertices, int[] indices, double[] normals, double[] texCoords) {
        Util.requireNonNull(vertices, "mesh vertices");
        Util.requireNonNull(indices, "mesh indices");
        if (vertices.length % 3 != 0) {
            throw new IllegalArgumentException("mesh vertices must hold x, y, z triples, but its length "
                    + vertices.length + " is not a multiple of 3");
        }
        if (indices.length % 3 != 0 || indices.length == 0) {
            throw new IllegalArgumentException("mesh indices must hold three per triangle and at least one triangle, "
                    + "but its length was " + indices.length);
        }
        for (int i = 0; i < vertices.length; i++) {
            if (!Double.isFinite(vertices[i])) {
                throw new IllegalArgumentException(
                        "mesh vertex " + i / 3 + " has a non-finite coordinate " + vertices[i]);
            }
        }
        int vertexCount = vertices.length / 3;
        for (int i = 0; i < indices.length; i++) {
            if (indices[i] < 0 || indices[i] >= vertexCount) {
                throw new IllegalArgumentException("mesh triangle " + i / 3 + " has vertex index " + indices[i]
                        + ", but indices must be in [0, " + (vertexCount - 1) + "]");
            }
        }
        if (normals != null) {
            if (normals.length != vertices.length) {
                throw new IllegalArgumentException("mesh normals must hold one x, y, z triple per vertex ("
                        + vertices.length + " values), but had " + normals.length);
            }
            for (int i = 0; i < normals.length; i += 3) {
                if (!(Double.isFinite(normals[i]) && Double.isFinite(normals[i + 1]) && Double.isFinite(normals[i + 2]))
                        || (normals[i] == 0 && normals[i + 1] == 0 && normals[i + 2] == 0)) {
                    throw new IllegalArgumentException("mesh normal " + i / 3 + " must be finite and non-zero");
                }
            }
        }
        if (texCoords != null) {
            if (texCoords.length != 2 * vertexCount) {
                throw new IllegalArgumentException("mesh texture coordinates must hold one u, v pair per vertex ("
                        + 2 * vertexCount + " values), but had " + texCoords.length);
            }
            for (int i = 0; i < texCoords.length; i++) {
                if (!Double.isFinite(texCoords[i])) {
                    throw new IllegalArgumentException(
                            "mesh texture coordinate " + i / 2 + " has a non-finite value " + texCoords[i]);
                }
            }
        }
        this.vertices = vertices.clone();
        this.indices = indices.clone();
        this.normals = normals == null ? null : normals.clone();
        this.texCoords = texCoords == null ? null : texCoords.clone();
    }

    /**
     * Number of triangles, including any of zero area.
     *
     * @return the triangle count
     */
    public int triangleCount() {
        return indices.length / 3;
    }

    /**
     * The number of vertices.
     *
     * @return the vertex count
     */
    public int vertexCount() {
        return vertices.length / 3;
    }

    /**
     * A copy of the vertex coordinates: x, y, z per vertex.
     *
     * @return a new array of x, y, z per vertex
     */
    public double[] getVertices() {
        return vertices.clone();
    }

    /**
     * A copy of the vertex indices: three per triangle.
     *
     * @return a new array of three 0-based vertex indices per triangle
     */
    public int[] getIndices() {
        return indices.clone();
    }

    /**
     * A copy of the per-vertex normals, or null for a flat-shaded mesh.
     *
     * @return a new array of x, y, z per vertex, or null
     */
    public double[] getNormals() {
        return normals == null ? null : normals.clone();
    }

    /**
     * A copy of the per-vertex texture coordinates, or null when the mesh has none.
     *
     * @return a new array of u, v per vertex, or null
     */
    public double[] getTexCoords() {
        return texCoords == null ? null : texCoords.clone();
    }

    /**
     * This mesh scaled by {@code scale} about the origin, then moved by (dx, dy, dz), with the same material.
     *
     * @param scale the scale factor, positive and finite
     * @param dx the translation along x
     * @param dy the translation along y
     * @param dz the translation along z
     * @return a new mesh
     * @throws IllegalArgumentException if {@code scale} is not positive and finite
     */
    public Mesh transformed(double scale, double dx, double dy, double dz) {
        Util.requirePositive(scale, "mesh scale");
        double[] moved = new double[vertices.length];
        for (int i = 0; i < moved.length; i += 3) {
            moved[i] = vertices[i] * scale + dx;
            moved[i + 1] = vertices[i + 1] * scale + dy;
            moved[i + 2] = vertices[i + 2] * scale + dz;
        }
        Mesh mesh = new Mesh(moved, indices, normals, texCoords);
        mesh.setMaterial(getMaterial()).setEmission(getEmission());
        return mesh;
    }

    /**
     * This mesh moved into place by {@code t}, with the same material and emission: what copying a model into a
     * scene stores (an {@link Instance} places it without the copy). Vertices are mapped as
     * {@link Transform#apply} maps points, normals by the inverse transpose.
     *
     * @param t the placement; not null
     * @return a new mesh
     */
    public Mesh transformed(Transform t) {
        Util.requireNonNull(t, "mesh transform");
        double[] m = t.toMatrix();
        double[] moved = new double[vertices.length];
        for (int i = 0; i < moved.length; i += 3) {
            double x = vertices[i], y = vertices[i + 1], z = vertices[i + 2];
            for (int row = 0; row < 3; row++) {
                moved[i + row] = m[4 * row] * x + m[4 * row + 1] * y + m[4 * row + 2] * z + m[4 * row + 3];
            }
        }
        double[] turned = null;
        if (normals != null) {
            double[] inverse = t.toInverseMatrix();
            turned = new double[normals.length];
            for (int i = 0; i < turned.length; i += 3) {
                double x = normals[i], y = normals[i + 1], z = normals[i + 2];
                for (int col = 0; col < 3; col++) {
                    turned[i + col] = inverse[col] * x + inverse[4 + col] * y + inverse[8 + col] * z;
                }
            }
        }
        Mesh mesh = new Mesh(moved, indices, turned, texCoords);
        mesh.setMaterial(getMaterial()).setEmission(getEmission());
        return mesh;
    }

    /**
     * Vertex {@code i} of the shared array.
     *
     * @param i the 0-based vertex index
     * @return a new point at the vertex
     */
    public Point vertex(int i) {
        return new Point(vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]);
    }

    /**
     * Whether triangle {@code i} has no area (it can never be hit).
     *
     * @param i the 0-based triangle index
     * @return true when the triangle's vertices are collinear or coincide
     */
    public boolean isDegenerate(int i) {
        return !WatertightTriangle.hasArea(
                vertices, 3 * indices[3 * i], 3 * indices[3 * i + 1], 3 * indices[3 * i + 2]);
    }

    @Override
    public Vector getNormal(Point point) {
        // The course API has no triangle index: use the triangle whose plane lies closest to the point.
        int best = -1;
        double bestDistance = Double.POSITIVE_INFINITY;
        for (int i = 0; i < triangleCount(); i++) {
            Vector n = triangleNormal(i);
            if (n == null) continue;
            int a = 3 * indices[3 * i];
            double d = Math.abs((point.x - vertices[a]) * n.x
                    + (point.y - vertices[a + 1]) * n.y
                    + (point.z - vertices[a + 2]) * n.z);
            if (d < bestDistance) {
                bestDistance = d;
                best = i;
            }
        }
        return triangleNormal(best);
    }

    private Vector triangleNormal(int i) {
        return WatertightTriangle.normal(vertices, 3 * indices[3 * i], 3 * indices[3 * i + 1], 3 * indices[3 * i + 2]);
    }

    @Override
    public boolean intersect(Ray ray, double tMin, double tMax, HitRecord hit) {
        boolean found = false;
        for (int i = 0; i < indices.length; i += 3) {
            if (WatertightTriangle.intersect(
                    vertices,
                    3 * indices[i],
                    3 * indices[i + 1],
                    3 * indices[i + 2],
                    WatertightTriangle.ALL_EDGES_SHARED,
                    ray,
                    tMin,
                    tMax,
                    hit)) {
                tMax = hit.t;
                hit.geometry = this;
                hit.part = i / 3;
                found = true;
            }
        }
        return found;
    }

    @Override
    public BoundingBox getBoundingBox() {
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int index : indices) {
            int a = 3 * index;
            x0 = Math.min(x0, vertices[a]);
            y0 = Math.min(y0, vertices[a + 1]);
            z0 = Math.min(z0, vertices[a + 2]);
            x1 = Math.max(x1, vertices[a]);
            y1 = Math.max(y1, vertices[a + 1]);
            z1 = Math.max(z1, vertices[a + 2]);
        }
        return new BoundingBox(x0, y0, z0, x1, y1, z1);
    }

    @Override
    public void completeHit(Ray ray, HitRecord hit) {
        int i = hit.part;
        int a = 3 * indices[3 * i], b = 3 * indices[3 * i + 1], c = 3 * indices[3 * i + 2];
        WatertightTriangle.completeHit(vertices, a, b, c, hit);
        if (!WatertightTriangle.setNormal(vertices, a, b, c, hit)) hit.setNormal(0, 0, 0); // never for a hit
        if (normals != null) interpolateShadingNormal(a, b, c, hit);
        if (texCoords != null) {
            double b1 = hit.u, b2 = hit.v, b0 = 1 - b1 - b2;
            int ta = 2 * indices[3 * i], tb = 2 * indices[3 * i + 1], tc = 2 * indices[3 * i + 2];
            hit.texU = b0 * texCoords[ta] + b1 * texCoords[tb] + b2 * texCoords[tc];
            hit.texV = b0 * texCoords[ta + 1] + b1 * texCoords[tb + 1] + b2 * texCoords[tc + 1];
        }
    }

    /**
     * Sets the shading normal to the barycentric blend of the vertex normals at offsets a, b, c, normalized (left
     * at the geometric normal if they cancel out); the vertex normals define the outside, as in pbrt, so the
     * geometric normal is flipped to their side.
     */
    private void interpolateShadingNormal(int a, int b, int c, HitRecord hit) {
        double b1 = hit.u, b2 = hit.v;
        double b0 = 1 - b1 - b2;
        double nx = b0 * normals[a] + b1 * normals[b] + b2 * normals[c];
        double ny = b0 * normals[a + 1] + b1 * normals[b + 1] + b2 * normals[c + 1];
        double nz = b0 * normals[a + 2] + b1 * normals[b + 2] + b2 * normals[c + 2];
        if (nx == 0 && ny == 0 && nz == 0) return;
        // Vector.normalize's arithmetic.
        double f = Vector.unitFactor(nx, ny, nz);
        if (f > 0) {
            hit.snx = nx * f;
            hit.sny = ny * f;
            hit.snz = nz * f;
        } else {
            hit.snx = Vector.unitComponent(nx, nx, ny, nz);
            hit.sny = Vector.unitComponent(ny, nx, ny, nz);
            hit.snz = Vector.unitComponent(nz, nx, ny, nz);
        }
        if (hit.snx * hit.nx + hit.sny * hit.ny + hit.snz * hit.nz < 0) {
            hit.nx = -hit.nx;
            hit.ny = -hit.ny;
            hit.nz = -hit.nz;
        }
    }
}
