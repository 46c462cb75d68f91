// Test executable of Hyperbolic_surface_mesh_2: every case registered by the test_*.cpp files.
#include "cgal_hc_test.h"

int main(int argc, char** argv) { return cgal_hc_test::run_all(argc, argv); }
