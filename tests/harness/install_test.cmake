# Installs the build into PREFIX and runs the installed masonry-joint from
# there (issue 39): its --data default must be the installed
# share/masonry-joint/calibration_data, and validate of one series must pass.
#   cmake -DBUILD=... -DPREFIX=... -P install_test.cmake
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()
set(exe ${PREFIX}/bin/masonry-joint)
execute_process(COMMAND ${exe} validate --help WORKING_DIRECTORY ${PREFIX} OUTPUT_VARIABLE help RESULT_VARIABLE rc)
if(NOT help MATCHES "share/masonry-joint/calibration_data")
  message(FATAL_ERROR "the installed --data default is not the installed data:\n${help}")
endif()
execute_process(COMMAND ${exe} validate --series vdp_monotonic_shear --no-plots --quiet --out ${PREFIX}/out
  WORKING_DIRECTORY ${PREFIX} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT out MATCHES "0 failed")
  message(FATAL_ERROR "installed validate: exit ${rc}\n${out}${err}")
endif()
message(STATUS "installed validate passed:\n${out}")
