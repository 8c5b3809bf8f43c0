#pragma once
// An OpenMesh importer that records vertices and faces exactly as a reader hands them over.
//
// Why not read into an OpenMesh mesh: OpenMesh's own importer (ImporterT) adds faces to a
// half-edge structure, which cannot hold a "complex" face (one that would make an edge
// non-manifold or a vertex a second fan). It then gives that face private copies of its
// vertices, and it drops faces that repeat a vertex. Read that way, bun_zipper_res4.ply comes back
// with 798 vertices instead of 453: its 115 refused faces float free with their own vertices, the
// mesh shows 464 boundary edges instead of 26, and the file's 70 non-manifold edges and 40
// duplicate faces can no longer be seen.
// Topology must be judged on the face list the file gives, so this recorder keeps every face and
// every index as read, even out-of-range ones, for mesh_io.cpp to check.
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>

#include <cstdint>
#include <vector>

namespace eikon {

class OpenMeshFaceRecorder : public OpenMesh::IO::BaseImporter {
public:
    std::vector<OpenMesh::Vec3d> points;
    std::vector<std::vector<int>> faces;  // vertex indices as read; may be out of range

    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override;
    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override;
    OpenMesh::VertexHandle add_vertex() override;
    OpenMesh::FaceHandle add_face(const VHandles& vertices) override;
    void set_point(OpenMesh::VertexHandle v, const OpenMesh::Vec3f& p) override;
    size_t n_vertices() const override { return points.size(); }
    size_t n_faces() const override { return faces.size(); }
    size_t n_edges() const override { return 0; }
    void reserve(unsigned int nVertices, unsigned int, unsigned int nFaces) override;

    // Half-edge construction is only used by OpenMesh's own .om format, which we do not read.
    OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
        return OpenMesh::HalfedgeHandle();
    }
    OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override {
        return OpenMesh::FaceHandle();
    }
    void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
    void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
    void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}

    // Attributes (normals, colours, texture coordinates, status): a refractive object needs none.
    void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                            const std::vector<OpenMesh::Vec2f>&) override {}
    void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                            const std::vector<OpenMesh::Vec3f>&) override {}
    void set_face_texindex(OpenMesh::FaceHandle, int) override {}
    void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
    void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
    void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
    void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
    void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void request_face_texcoords2D() override {}
    void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
    void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
    void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
    void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
    void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
    void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
    void add_texture_information(int, std::string) override {}
};

}  // namespace eikon
