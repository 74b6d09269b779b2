# The one-way module order, checked on the sources (a ctest test; runs without
# Python):
#   cmake -DMANIFEST=<build>/stochtex_modules.cmake -DROOT=<src>/stochtex -P check_module_includes.cmake
# MANIFEST is written by stochtex_module() (cmake/stochtex_module.cmake) from
# the modules' declarations, so the DEPENDS lists there are the only source.
# Fails, naming file, line and include, when
#   * a module declares a dependency on a module that is not before it in
#     STOCHTEX_MODULE_ORDER (or on no module at all);
#   * a directory under ROOT is not a declared module;
#   * a module's .h/.cpp/.glsl includes stochtex/<other>/... where <other> is
#     neither the module itself nor in its transitive DEPENDS.
cmake_minimum_required(VERSION 3.25)
foreach(var MANIFEST ROOT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_module_includes: pass -D${var}=...")
  endif()
endforeach()
include(${MANIFEST})
get_filename_component(ROOT ${ROOT} ABSOLUTE)

set(problems 0)
macro(problem)
  string(CONCAT text ${ARGN})
  message(NOTICE "${text}")
  math(EXPR problems "${problems} + 1")
endmacro()

# The declared dependencies against the one-way order.
string(REPLACE ";" " -> " order_text "${STOCHTEX_MODULE_ORDER}")
foreach(module IN LISTS STOCHTEX_MODULES)
  list(FIND STOCHTEX_MODULE_ORDER ${module} rank)
  if(rank LESS 0)
    problem("module ${module}: not in STOCHTEX_MODULE_ORDER (${order_text})")
    continue()
  endif()
  foreach(dep IN LISTS STOCHTEX_MODULE_DEPENDS_${module})
    list(FIND STOCHTEX_MODULE_ORDER ${dep} dep_rank)
    if(NOT dep IN_LIST STOCHTEX_MODULES)
      problem("module ${module}: DEPENDS ${dep}, which is not a declared module")
    elseif(NOT dep_rank LESS rank)
      problem("module ${module}: may not depend on ${dep}, which comes after it in the one-way order "
              "(${order_text})")
    endif()
  endforeach()
endforeach()

# Every directory under ROOT is a declared module.
file(GLOB entries LIST_DIRECTORIES true RELATIVE ${ROOT} ${ROOT}/*)
foreach(entry IN LISTS entries)
  if(IS_DIRECTORY ${ROOT}/${entry} AND NOT entry IN_LIST STOCHTEX_MODULES)
    problem("${ROOT}/${entry}/: not a declared module (no stochtex_module(NAME ${entry}) in its CMakeLists.txt)")
  endif()
endforeach()

# Includes, against the transitive closure of each module's DEPENDS.
set(files_checked 0)
foreach(module IN LISTS STOCHTEX_MODULES)
  set(allowed ${module})
  set(todo ${STOCHTEX_MODULE_DEPENDS_${module}})
  while(todo)
    list(POP_FRONT todo dep)
    if(NOT dep IN_LIST allowed)
      list(APPEND allowed ${dep})
      list(APPEND todo ${STOCHTEX_MODULE_DEPENDS_${dep}})
    endif()
  endwhile()
  list(REMOVE_AT allowed 0)
  list(SORT allowed)
  if(NOT allowed)
    set(allowed_text "nothing but itself")
  else()
    string(REPLACE ";" ", " allowed_text "${allowed}")
  endif()

  file(GLOB_RECURSE sources ${ROOT}/${module}/*.h ${ROOT}/${module}/*.cpp ${ROOT}/${module}/*.glsl)
  list(SORT sources)
  foreach(source IN LISTS sources)
    math(EXPR files_checked "${files_checked} + 1")
    # Whole file first: most files have no cross-module include worth a line scan.
    file(STRINGS ${source} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]stochtex/")
    if(NOT includes)
      continue()
    endif()
    file(STRINGS ${source} lines)
    set(number 0)
    foreach(line IN LISTS lines)
      math(EXPR number "${number} + 1")
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*[<\"](stochtex/([A-Za-z0-9_]+)/[^>\"]*)")
        set(header ${CMAKE_MATCH_1})
        set(other ${CMAKE_MATCH_2})
        if(NOT other STREQUAL module AND NOT other IN_LIST allowed)
          problem("${source}:${number}: module ${module} includes ${header}, but may use only ${allowed_text} "
                  "(its DEPENDS in ${module}/CMakeLists.txt, transitively)")
        endif()
      endif()
    endforeach()
  endforeach()
endforeach()

list(LENGTH STOCHTEX_MODULES module_count)
if(problems GREATER 0)
  message(FATAL_ERROR "module order: ${problems} problem(s) in ${files_checked} files of ${module_count} modules")
endif()
message(STATUS "module order: ${files_checked} files of ${module_count} modules follow their declared DEPENDS")
