# Links a relocatable object for `user=` as a program would that has no C++
# runtime of its own (the C++ driver without its default libraries, every
# symbol resolved: -Wl,--no-undefined), the exit utility from a stand-in, and
# checks the result as a shipped library (check_linux_library.cmake). Run as:
# cmake -DOBJECT=<o> -DCXX=<c++> -DEXIT=<xplb_exit_|xit_> -DOBJDUMP=<objdump>
# -DWORK=<dir> -P link_linux_object.cmake
cmake_policy(VERSION 3.25)
file(MAKE_DIRECTORY ${WORK})
get_filename_component(name ${OBJECT} NAME_WE)
file(WRITE ${WORK}/${name}_exit.cpp "extern \"C\" void ${EXIT}() {}\n")
set(LIBRARY ${WORK}/lib${name}.so)
execute_process(COMMAND ${CXX} -shared -fPIC -nodefaultlibs -Wl,--no-undefined -o ${LIBRARY} ${OBJECT}
                        ${WORK}/${name}_exit.cpp -lm -lc -lgcc_s -lgcc
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${OBJECT} does not link without a C++ runtime:\n${err}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/check_linux_library.cmake)
