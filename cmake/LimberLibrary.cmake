# Libraries with one include root each, so that the link lists enforce the dependency direction
# (house style §13): a library sees its own headers and those of the libraries it links, and an
# include of any other library's header is a compile error.
#
# Headers stay beside their sources in solver/<folder>/ and are included as "<folder>/x.h". The
# root of target T is ${CMAKE_BINARY_DIR}/include/T, holding one symbolic link <folder> ->
# the source folder, made at configure time; no header is copied or moved.

# limber_include_root(<target> <PUBLIC|PRIVATE|INTERFACE>)
#   Gives <target> the include root described above for the folder of the calling
#   CMakeLists.txt (the `limber` command uses it PRIVATE for its "app/x.h" headers).
function(limber_include_root target scope)
  get_filename_component(folder "${CMAKE_CURRENT_SOURCE_DIR}" NAME)
  set(root "${CMAKE_BINARY_DIR}/include/${target}")
  file(MAKE_DIRECTORY "${root}")
  set(link "${root}/${folder}")
  if(IS_SYMLINK "${link}")
    file(READ_SYMLINK "${link}" current)
    if(NOT current STREQUAL CMAKE_CURRENT_SOURCE_DIR)
      file(REMOVE "${link}")
    endif()
  endif()
  if(NOT IS_SYMLINK "${link}")
    file(CREATE_LINK "${CMAKE_CURRENT_SOURCE_DIR}" "${link}" SYMBOLIC)
  endif()
  target_include_directories(${target} ${scope} "${root}")
endfunction()

# limber_library(<target> [INTERFACE] [FLAT] [SOURCES src...] [PUBLIC dep...] [PRIVATE dep...])
#   Adds library <target> from the sources of the calling folder, with that folder as its only
#   include root, and links it: PUBLIC what its headers include, PRIVATE what only its sources
#   include. INTERFACE: a header-only library (no sources, PUBLIC deps become INTERFACE).
#   FLAT: the folder itself is the root (render/ and report/ include their headers as "x.h").
function(limber_library target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "INTERFACE;FLAT" "" "SOURCES;PUBLIC;PRIVATE")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "limber_library(${target}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(arg_INTERFACE)
    if(arg_SOURCES OR arg_PRIVATE)
      message(FATAL_ERROR "limber_library(${target}): INTERFACE takes neither SOURCES nor PRIVATE")
    endif()
    add_library(${target} INTERFACE)
    set(public INTERFACE)
  else()
    add_library(${target} ${arg_SOURCES})
    set(public PUBLIC)
  endif()
  if(arg_FLAT)
    target_include_directories(${target} ${public} "${CMAKE_CURRENT_SOURCE_DIR}")
  else()
    limber_include_root(${target} ${public})
  endif()
  if(arg_PUBLIC)
    target_link_libraries(${target} ${public} ${arg_PUBLIC})
  endif()
  if(arg_PRIVATE)
    target_link_libraries(${target} PRIVATE ${arg_PRIVATE})
  endif()
endfunction()
