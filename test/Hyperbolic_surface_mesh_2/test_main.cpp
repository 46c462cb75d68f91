// Test executable of Hyperbolic_surface_mesh_2: every case registered by the test_*.cpp files (or those whose
// name contains argv[1]); `--remesh-all-demo-meshes` runs the long loop over all demo meshes of genus >= 2.
#include "cgal_hc_test.h"

#include <cstring>

int remesh_all_demo_meshes(); // test_remesh.cpp

int main(int argc, char** argv)
{
  if(argc > 1 && std::strcmp(argv[1], "--remesh-all-demo-meshes") == 0) return remesh_all_demo_meshes() == 0 ? 0 : 1;
  return cgal_hc_test::run_all(argc, argv);
}
