# cmake -P script run by CTest (tests/install/CMakeLists.txt): installs BUILD_DIR into PREFIX,
# checks the installed layout, then builds CONSUMER_SOURCE with only PREFIX to find deploydyn in,
# and runs it on MODEL. Any failing step fails the test with its output.
cmake_minimum_required(VERSION 3.25)

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${what} failed (${result}):\n  ${ARGN}\n${output}")
  endif()
  message(STATUS "${what}: ok")
  set(step_output "${output}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${PREFIX} ${CONSUMER_BUILD})
run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX})

foreach(file bin/deploydyn include/deploydyn/model/model.hpp include/deploydyn/io/model_loader.hpp
             include/deploydyn/runs/run_to_folder.hpp include/deploydyn/output/vtk_writer.hpp)
  if(NOT EXISTS ${PREFIX}/${file})
    message(FATAL_ERROR "not installed: ${PREFIX}/${file}")
  endif()
endforeach()
file(GLOB_RECURSE libraries ${PREFIX}/lib*/libdeploydyn.a)
file(GLOB_RECURSE configs ${PREFIX}/lib*/cmake/deploydyn/deploydynConfig.cmake)
if(NOT libraries OR NOT configs)
  message(FATAL_ERROR "not installed: lib/.../libdeploydyn.a or lib/.../cmake/deploydyn/deploydynConfig.cmake")
endif()
run_step("installed command" ${PREFIX}/bin/deploydyn check ${MODEL})
# The plot scripts, installed beside the command, from a folder outside the source tree.
run_step("installed run" ${PREFIX}/bin/deploydyn run ${MODEL} --quiet --set analysis.end=0.1 --out ${PREFIX}/run)
execute_process(COMMAND ${PREFIX}/bin/deploydyn plot run --what driver --format png --out plots
                WORKING_DIRECTORY ${PREFIX} RESULT_VARIABLE plotted OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT plotted EQUAL 0 OR NOT EXISTS ${PREFIX}/plots/driver.png)
  message(FATAL_ERROR "installed deploydyn plot failed (${plotted}):\n${output}")
endif()

# The modules loaded on demand (util/optional_module.hpp) are installed, and the installed
# command finds its own, beside it (LD_DEBUG=files: the loader names every object it opens).
foreach(module deploydyn_hdf5 deploydyn_umfpack)
  file(GLOB_RECURSE found ${PREFIX}/lib*/deploydyn/${module}.so)
  if(NOT found)
    message(FATAL_ERROR "not installed: ${PREFIX}/lib/deploydyn/${module}.so")
  endif()
endforeach()
file(GLOB_RECURSE installed_hdf5_module ${PREFIX}/lib*/deploydyn/deploydyn_hdf5.so)
run_step("installed command with output.hdf5" ${CMAKE_COMMAND} -E env LD_DEBUG=files ${PREFIX}/bin/deploydyn run
         ${MODEL} --set output.hdf5=true --set analysis.end=0.01 --quiet --out ${CONSUMER_BUILD}/hdf5_run)
string(FIND "${step_output}" "${installed_hdf5_module}" at)
if(at LESS 0 OR NOT EXISTS ${CONSUMER_BUILD}/hdf5_run/history.h5)
  message(FATAL_ERROR "the installed command did not write history.h5 with ${installed_hdf5_module}:\n${step_output}")
endif()

# Only the prefix: no package registry, and the consumer finds Eigen, yaml-cpp, fmt and FCL itself
# through deploydynConfig.cmake.
run_step("configure consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${CONSUMER_BUILD} -G ${GENERATOR}
         -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_CXX_FLAGS=${CXX_FLAGS}
         -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
file(STRINGS ${CONSUMER_BUILD}/CMakeCache.txt found REGEX "^deploydyn_DIR:")
string(FIND "${found}" "${PREFIX}/" at)
if(NOT at GREATER 0)
  message(FATAL_ERROR "the consumer found deploydyn elsewhere than in ${PREFIX}: ${found}")
endif()
run_step("build consumer" ${CMAKE_COMMAND} --build ${CONSUMER_BUILD})
run_step("run consumer" ${CONSUMER_BUILD}/consumer ${MODEL} ${CONSUMER_BUILD}/run)
message(STATUS "${step_output}")
