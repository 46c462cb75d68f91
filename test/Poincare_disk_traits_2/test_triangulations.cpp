#include "cgal_hc_test.h"
