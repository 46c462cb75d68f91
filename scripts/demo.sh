#!/usr/bin/env bash
# The main job: every package's demo on its bundled default input; results and SVG pictures go to build/output/.
source "$(dirname "$0")/common.sh"
install_missing_packages
configure_and_build -DBUILD_TESTING=OFF -DCGAL_HC_BUILD_EXAMPLES=ON -- run_demo
echo "Output folder: $BUILD_DIR/output"
