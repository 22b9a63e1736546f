# Installs BUILD_DIR into PREFIX and checks what an installed limber needs (tests/install).
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status}): ${errors}")
endif()

foreach(file bin/limber share/limber/cases/satellite_deployment.yaml share/limber/cases/satellite_panel.bdf
             share/limber/README.md share/limber/docs/case-format.md)
  if(NOT EXISTS ${PREFIX}/${file})
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()

execute_process(COMMAND ${PREFIX}/bin/limber --version OUTPUT_VARIABLE version RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT version MATCHES "limber ${VERSION}")
  message(FATAL_ERROR "installed limber --version: status ${status}, printed '${version}'")
endif()

# An installed case runs from a folder outside the checkout (10 ms of the slider-crank).
set(work ${PREFIX}/../run)
file(REMOVE_RECURSE ${work})
file(MAKE_DIRECTORY ${work})
execute_process(COMMAND ${PREFIX}/bin/limber run ${PREFIX}/share/limber/cases/slider_crank.yaml
                        --t-end 0.01 -o ${work}/slider_crank
                WORKING_DIRECTORY ${work} RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors)
if(NOT status EQUAL 0 OR NOT EXISTS ${work}/slider_crank/results.h5)
  message(FATAL_ERROR "installed limber run of an installed case failed (${status}): ${errors}")
endif()

# The installed Python module, imported by Debian's python3 from outside the checkout, runs the
# same installed case (PYTHONPATH: the prefix is not one of python3's own).
if(PYTHON)
  set(module_dir ${PREFIX}/${PYTHON_DIR})
  file(GLOB modules ${module_dir}/limber.*.so)
  if(NOT modules)
    message(FATAL_ERROR "not installed: the Python module in ${PYTHON_DIR}")
  endif()
  if(NOT EXISTS ${module_dir}/limber.pyi)
    message(FATAL_ERROR "not installed: the type stubs limber.pyi beside the module in ${PYTHON_DIR}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${module_dir}
                          ${PYTHON} -c "import limber, sys; r = limber.run(sys.argv[1], t_end=0.01); print(limber.__file__, r.status, len(r.time))"
                          ${PREFIX}/share/limber/cases/slider_crank.yaml
                  WORKING_DIRECTORY ${work} RESULT_VARIABLE status OUTPUT_VARIABLE printed ERROR_VARIABLE errors)
  if(NOT status EQUAL 0 OR NOT printed MATCHES "^${module_dir}/limber[^ ]* ok 11")
    message(FATAL_ERROR "installed Python module: status ${status}, printed '${printed}': ${errors}")
  endif()
  # limber.sweep's points are children of the installed executable, found beside the module
  # (<prefix>/bin/limber) with nothing on PATH.
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=LIMBER_EXECUTABLE PATH= PYTHONPATH=${module_dir}
                          ${PYTHON} -c "import limber, sys; s = limber.sweep(sys.argv[1], over=['integrator=galpha', 'step=1e-3'], t_end=0.01, output='sweep', jobs=1); print(s['status'], [p['status'] for p in s['points']])"
                          ${PREFIX}/share/limber/cases/slider_crank_rigid.yaml
                  WORKING_DIRECTORY ${work} RESULT_VARIABLE status OUTPUT_VARIABLE printed ERROR_VARIABLE errors)
  if(NOT status EQUAL 0 OR NOT printed MATCHES "^ok \\['ok'\\]")
    message(FATAL_ERROR "installed Python module's sweep: status ${status}, printed '${printed}': ${errors}")
  endif()
endif()
