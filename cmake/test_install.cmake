# CTest script: install the library into a scratch prefix, then configure, build and run a consumer project
# that calls find_package(CGAL_hyperbolic_conformal). Arguments: -DBUILD_DIR= -DSOURCE_DIR=
set(prefix "${BUILD_DIR}/install_test/prefix")
set(consumer_build "${BUILD_DIR}/install_test/consumer")
file(REMOVE_RECURSE "${BUILD_DIR}/install_test")
macro(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}")
  endif()
endmacro()
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/test/install_consumer" -B "${consumer_build}"
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build "${consumer_build}")
run("${consumer_build}/consumer")
