# littermap_module(NAME [PUBLIC deps...] [PRIVATE deps...])
# One library per module folder: every .cpp of the folder, headers included as "NAME/x.hpp".
function(littermap_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wnon-virtual-dtor)
  # GCC 12 reports a false -Wrestrict inside std::string's operator+ at -O2 (GCC bug 105329).
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-restrict)
    # Under ASan GCC 12 cannot see that a disengaged std::optional's payload is never read and
    # reports -Wmaybe-uninitialized on moving it (GCC bug 80635); the release build keeps it.
    if(CMAKE_BUILD_TYPE STREQUAL "Sanitize")
      target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
    endif()
  endif()
  if(LITTERMAP_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

function(littermap_module name)
  cmake_parse_arguments(ARG "" "" "PUBLIC;PRIVATE" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(NOT sources)  # a header-only module
    add_library(littermap_${name} INTERFACE)
    target_include_directories(littermap_${name} INTERFACE ${PROJECT_SOURCE_DIR}
                                                           ${PROJECT_BINARY_DIR}/generated)
    target_link_libraries(littermap_${name} INTERFACE ${ARG_PUBLIC})
    add_library(littermap::${name} ALIAS littermap_${name})
    return()
  endif()
  add_library(littermap_${name} STATIC ${sources})
  target_include_directories(littermap_${name} PUBLIC ${PROJECT_SOURCE_DIR}
                                                      ${PROJECT_BINARY_DIR}/generated)
  target_link_libraries(littermap_${name} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  littermap_warnings(littermap_${name})
  add_library(littermap::${name} ALIAS littermap_${name})
endfunction()
