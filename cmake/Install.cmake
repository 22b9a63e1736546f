# `cmake --install build` and `cpack -G DEB` (docs/install.md): the `limber` command on PATH,
# the Python module `limber`, and under share/limber the example cases, the documentation and the
# README, laid out as in the checkout: the cases' comments point at docs/*.md, which resolves
# from share/limber as it does from the checkout's root.
# limber reads no data files at run time (fonts and colour maps come from VTK), so an installed
# limber needs nothing else of the checkout.
include(GNUInstallDirs)

# The installed executable keeps the library folders it was linked against (Debian's HDF5 and
# Open MPI live outside the linker's default path); every limber library is static.
set_target_properties(limber PROPERTIES INSTALL_RPATH_USE_LINK_PATH TRUE)
install(TARGETS limber RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/cases/ DESTINATION ${CMAKE_INSTALL_DATADIR}/limber/cases)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/limber/docs)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/limber)

# The Python module, where Debian's python3 finds it under both /usr (the .deb) and /usr/local
# (its site folders include lib/python3.X/dist-packages under each; lib/python3/dist-packages
# only under /usr). The module is built for that one X (its file name says so).
if(LIMBER_BUILD_PYTHON)
  set(LIMBER_PYTHON_INSTALL_DIR "lib/python3.${Python3_VERSION_MINOR}/dist-packages" CACHE STRING
      "Where `cmake --install` puts the Python module, relative to the prefix")
  set_target_properties(limber_python PROPERTIES INSTALL_RPATH_USE_LINK_PATH TRUE)
  install(TARGETS limber_python LIBRARY DESTINATION ${LIMBER_PYTHON_INSTALL_DIR})
  install(FILES ${PROJECT_SOURCE_DIR}/solver/python/limber.pyi DESTINATION ${LIMBER_PYTHON_INSTALL_DIR})
endif()

# A Debian package whose dependencies dpkg-shlibdeps reads off the executable's shared
# libraries (SUNDIALS, ARPACK, HDF5, matio, VTK, ...), so that apt installs them with it.
set(CPACK_PACKAGE_NAME limber)
set(CPACK_PACKAGE_VENDOR "limber")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "dynamics of mechanisms with flexible parts")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
    "Component mode synthesis on a floating frame of reference: flexible bodies reduced to "
    "normal and static modes, joints, drivers and force elements integrated as a DAE, joint "
    "reactions, offscreen rendering and HTML reports.")
set(CPACK_PACKAGE_CONTACT "limber maintainers <limber@localhost>")
set(CPACK_PACKAGE_INSTALL_DIRECTORY limber)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What limber loads or reads at run time without linking it: Mesa's EGL and drivers (offscreen
# rendering) and dygraphs (the reports' charts, /usr/share/javascript/dygraphs); ffmpeg makes
# the videos and is only recommended (without it, PNG frames only).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl-mesa0, libgl1-mesa-dri, libjs-dygraphs")
# The Python module: the python3 it was built for, and numpy for its arrays.
if(LIMBER_BUILD_PYTHON)
  math(EXPR next_minor "${Python3_VERSION_MINOR} + 1")
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS
         ", python3 (>= 3.${Python3_VERSION_MINOR}~), python3 (<< 3.${next_minor}), python3-numpy")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "ffmpeg")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
include(CPack)
