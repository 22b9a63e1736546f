# Every third-party dependency of limber, all from Debian 12 packages
# (scripts/install-deps.sh installs them; GoogleTest and Google Benchmark with --tests).
# Nothing is downloaded here.

find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(yaml-cpp REQUIRED)
find_package(CLI11 REQUIRED)
find_package(fmt REQUIRED)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(BLAS REQUIRED)
find_package(LAPACK REQUIRED)
# SUNDIALS 6.4: targets SUNDIALS::ida_shared, nvecserial_shared, sunlinsoldense_shared, ...
find_package(SUNDIALS 6 REQUIRED CONFIG)

# arpack-ng and CHOLMOD ship no CMake package on Debian 12: locate them directly.
find_library(ARPACK_LIBRARY NAMES arpack REQUIRED)
add_library(limber_arpack INTERFACE)
target_link_libraries(limber_arpack INTERFACE ${ARPACK_LIBRARY} LAPACK::LAPACK BLAS::BLAS)

find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY NAMES cholmod REQUIRED)
find_library(SUITESPARSE_CONFIG_LIBRARY NAMES suitesparseconfig REQUIRED)
add_library(limber_cholmod INTERFACE)
target_include_directories(limber_cholmod SYSTEM INTERFACE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(limber_cholmod INTERFACE
  ${CHOLMOD_LIBRARY} ${SUITESPARSE_CONFIG_LIBRARY} LAPACK::LAPACK BLAS::BLAS)
# KLU (the same SuiteSparse package): generalized-α's sparse iteration matrix (integrate/sparse_lu.h).
find_library(KLU_LIBRARY NAMES klu REQUIRED)
find_library(BTF_LIBRARY NAMES btf REQUIRED)
find_library(AMD_LIBRARY NAMES amd REQUIRED)
find_library(COLAMD_LIBRARY NAMES colamd REQUIRED)
add_library(limber_klu INTERFACE)
target_include_directories(limber_klu SYSTEM INTERFACE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(limber_klu INTERFACE
  ${KLU_LIBRARY} ${BTF_LIBRARY} ${AMD_LIBRARY} ${COLAMD_LIBRARY} ${SUITESPARSE_CONFIG_LIBRARY})

# MATLAB .mat v5 files of `limber linearize` (run/linear_mat_file.h). matio ships no CMake
# package on Debian 12 (only a pkg-config file): located directly.
find_path(MATIO_INCLUDE_DIR matio.h REQUIRED)
find_library(MATIO_LIBRARY NAMES matio REQUIRED)
add_library(limber_matio INTERFACE)
target_include_directories(limber_matio SYSTEM INTERFACE ${MATIO_INCLUDE_DIR})
target_link_libraries(limber_matio INTERFACE ${MATIO_LIBRARY})

# Rendering (render/ only; the solver links nothing graphical). VTK 9.1's named modules, each
# linked by name where it is used, never ${VTK_LIBRARIES}. OpenGL::EGL: the headless context
# (docs/rendering.md). libdeflate and Threads: the PNG writer threads (render/png_encoding.h);
# libdeflate ships no CMake package on Debian 12 (only a pkg-config file): located directly.
# render/ and its tests, then report/'s charts. Debian's ChartsCore pulls VTK::mpi, whose link
# interface names MPI::MPI_C, so MPI must be found first.
find_package(MPI REQUIRED COMPONENTS C)
# `limber sweep` shares its grid among MPI ranks (docs/sweep.md) when built with MPI: on by
# default where MPI is found (Debian's Open MPI: openmpi-bin, libopenmpi-dev).
if(MPI_C_FOUND)
  option(LIMBER_WITH_MPI "limber sweep distributes its grid points over MPI ranks" ON)
else()
  set(LIMBER_WITH_MPI OFF)
endif()
find_package(VTK REQUIRED COMPONENTS
  CommonCore CommonDataModel CommonExecutionModel FiltersCore FiltersSources FiltersGeneral
  IOImage IOXML IOXMLParser RenderingCore RenderingOpenGL2 RenderingAnnotation
  RenderingFreeType InteractionStyle glew
  ChartsCore ViewsContext2D RenderingContext2D RenderingContextOpenGL2)
find_package(OpenGL REQUIRED COMPONENTS EGL)
find_path(LIBDEFLATE_INCLUDE_DIR libdeflate.h REQUIRED)
find_library(LIBDEFLATE_LIBRARY NAMES deflate REQUIRED)
add_library(limber_libdeflate INTERFACE)
target_include_directories(limber_libdeflate SYSTEM INTERFACE ${LIBDEFLATE_INCLUDE_DIR})
target_link_libraries(limber_libdeflate INTERFACE ${LIBDEFLATE_LIBRARY})
find_package(Threads REQUIRED)

add_library(limber_hdf5 INTERFACE)
target_include_directories(limber_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS})
target_link_libraries(limber_hdf5 INTERFACE ${HDF5_C_LIBRARIES})
target_compile_definitions(limber_hdf5 INTERFACE ${HDF5_C_DEFINITIONS})

# The Python module (solver/python, docs/python.md): pybind11 for Debian's python3 (pybind11-dev,
# python3-pybind11; numpy, python3-numpy, only at run time). /usr/bin/python3 first, not an
# interpreter earlier on PATH (pyenv, a virtualenv) whose ABI or site folders differ;
# -DPython3_EXECUTABLE=... chooses another. Found before pybind11, which then uses it.
if(LIMBER_BUILD_PYTHON)
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the module is built for")
  endif()
  find_package(Python3 REQUIRED COMPONENTS Interpreter Development.Module)
  find_package(pybind11 2.10 REQUIRED CONFIG)
endif()

if(LIMBER_BUILD_TESTS)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()
if(LIMBER_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
