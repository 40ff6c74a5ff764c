/** Wavefront OBJ meshes: a bounded, fuzzed reader (vertices, faces, normals) and a writer. JDK only. */
package obj;
