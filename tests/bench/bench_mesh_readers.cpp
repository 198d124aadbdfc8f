// Our validating OBJ/PLY readers (inlay::loadMesh) against OpenMesh 9's readers
// (OpenMesh::IO::read_mesh) feeding a triangle-soup importer that keeps every face OpenMesh's
// readers hand it (so OpenMesh's TriMesh cannot drop non-manifold faces): faces kept and load
// time (median of 5) per file. It measures whether the importers could switch to OpenMesh
// (README, "Meshes").
//
// usage: bench_mesh_readers OUT.csv FILE.obj|FILE.ply ...
#include "inlay/modeling/mesh.h"

#include <OpenMesh/Core/IO/MeshIO.hh>  // before the mesh headers
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <vector>

namespace {

using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// OpenMesh's own importer for everything but faces: a face is recorded as a fan of triangles
// over the reader's vertex handles (their indices), never added to the half-edge mesh, so
// none is refused. add_face returns an invalid handle: readers then skip per-face properties.
class SoupImporter : public OpenMesh::IO::ImporterT<OmMesh> {
 public:
  explicit SoupImporter(OmMesh& m) : ImporterT<OmMesh>(m) {}
  OpenMesh::FaceHandle add_face(const VHandles& v) override {
    for (size_t k = 2; k < v.size(); ++k) soup.push_back({v[0].idx(), v[k - 1].idx(), v[k].idx()});
    return OpenMesh::FaceHandle();
  }
  std::vector<std::array<int, 3>> soup;
};

double medianMs(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3)
    return std::fprintf(stderr, "usage: bench_mesh_readers OUT.csv FILE.obj|FILE.ply ...\n"), 2;
  std::ofstream csv(argv[1]);
  csv << "file,ours_triangles,ours_ms,openmesh_soup_triangles,openmesh_soup_ms,openmesh_trimesh_faces,openmesh_trimesh_ms\n";
  for (int a = 2; a < argc; ++a) {
    const std::string path = argv[a];
    using Clock = std::chrono::steady_clock;
    auto ms = [](Clock::time_point t) {
      return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
    };
    std::vector<double> ours, soup, tri;
    size_t oursTriangles = 0, soupTriangles = 0, triFaces = 0;
    for (int run = 0; run < 5; ++run) {
      auto t0 = Clock::now();
      const auto m = inlay::loadMesh(path);
      ours.push_back(ms(t0));
      oursTriangles = m.ok() ? m->triangles.size() : 0;

      OmMesh om;
      SoupImporter importer(om);
      OpenMesh::IO::Options opt;
      t0 = Clock::now();
      const bool ok = OpenMesh::IO::IOManager().read(path, importer, opt);
      soup.push_back(ms(t0));
      soupTriangles = ok ? importer.soup.size() : 0;

      OmMesh plain;
      t0 = Clock::now();
      const bool okPlain = OpenMesh::IO::read_mesh(plain, path);
      tri.push_back(ms(t0));
      triFaces = okPlain ? plain.n_faces() : 0;
    }
    csv << path << ',' << oursTriangles << ',' << medianMs(ours) << ',' << soupTriangles << ','
        << medianMs(soup) << ',' << triFaces << ',' << medianMs(tri) << '\n';
    std::printf(
        "%s: ours %zu tris %.1f ms | OpenMesh soup %zu tris %.1f ms | OpenMesh TriMesh %zu faces %.1f ms\n",
        path.c_str(), oursTriangles, medianMs(ours), soupTriangles, medianMs(soup), triFaces,
        medianMs(tri));
  }
  return 0;
}
