# GMP, MPFR and MPFI (Debian's libgmp-dev, libmpfr-dev, libmpfi-dev ship no CMake package): found
# by header and library, and given as the imported targets anisocert::GMP, anisocert::MPFR and
# anisocert::MPFI that numbers/ links. Included by the project (CMakeLists.txt) and, installed
# beside anisocertConfig.cmake, by find_package(anisocert), so that the installed package names
# the libraries found on the consumer's machine rather than paths from the build machine.
# Sets anisocert_ARITHMETIC_MISSING to what was not found (empty when all were).
set(anisocert_ARITHMETIC_MISSING "")
foreach(_anisocert_lib IN ITEMS GMP MPFR MPFI)
  string(TOLOWER ${_anisocert_lib} _anisocert_name)
  find_path(${_anisocert_lib}_INCLUDE_DIR ${_anisocert_name}.h)
  find_library(${_anisocert_lib}_LIBRARY ${_anisocert_name})
  if(NOT ${_anisocert_lib}_INCLUDE_DIR OR NOT ${_anisocert_lib}_LIBRARY)
    list(APPEND anisocert_ARITHMETIC_MISSING ${_anisocert_lib})
  elseif(NOT TARGET anisocert::${_anisocert_lib})
    add_library(anisocert::${_anisocert_lib} UNKNOWN IMPORTED)
    set_target_properties(anisocert::${_anisocert_lib} PROPERTIES
      IMPORTED_LOCATION "${${_anisocert_lib}_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${${_anisocert_lib}_INCLUDE_DIR}")
  endif()
endforeach()
# MPFI is built on MPFR, MPFR on GMP.
if(NOT anisocert_ARITHMETIC_MISSING)
  set_property(TARGET anisocert::MPFR PROPERTY INTERFACE_LINK_LIBRARIES anisocert::GMP)
  set_property(TARGET anisocert::MPFI PROPERTY INTERFACE_LINK_LIBRARIES anisocert::MPFR)
endif()
unset(_anisocert_lib)
unset(_anisocert_name)
