#include "sim/openmesh_face_recorder.h"

namespace eikon {

OpenMesh::VertexHandle OpenMeshFaceRecorder::add_vertex(const OpenMesh::Vec3f& p) {
    return add_vertex(OpenMesh::Vec3d(p[0], p[1], p[2]));
}

OpenMesh::VertexHandle OpenMeshFaceRecorder::add_vertex(const OpenMesh::Vec3d& p) {
    points.push_back(p);
    return OpenMesh::VertexHandle(int(points.size()) - 1);
}

// Readers that learn positions later (PLY with its properties in an unusual order) add the
// vertex first and set its point afterwards.
OpenMesh::VertexHandle OpenMeshFaceRecorder::add_vertex() {
    return add_vertex(OpenMesh::Vec3d(0.0, 0.0, 0.0));
}

void OpenMeshFaceRecorder::set_point(OpenMesh::VertexHandle v, const OpenMesh::Vec3f& p) {
    if (v.idx() >= 0 && size_t(v.idx()) < points.size())
        points[size_t(v.idx())] = OpenMesh::Vec3d(p[0], p[1], p[2]);
}

OpenMesh::FaceHandle OpenMeshFaceRecorder::add_face(const VHandles& vertices) {
    std::vector<int>& face = faces.emplace_back();
    face.reserve(vertices.size());
    for (const OpenMesh::VertexHandle& v : vertices) face.push_back(v.idx());
    return OpenMesh::FaceHandle(int(faces.size()) - 1);
}

void OpenMeshFaceRecorder::reserve(unsigned int nVertices, unsigned int, unsigned int nFaces) {
    // Headers can lie (a corrupt count); reserve only what a plausible file would hold.
    const unsigned int cap = 1u << 24;
    points.reserve(nVertices < cap ? nVertices : cap);
    faces.reserve(nFaces < cap ? nFaces : cap);
}

}  // namespace eikon
