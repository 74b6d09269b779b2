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
#     neither the module itself nor in its transitive DEPENDS;
#   * a file includes a path that does not start with stochtex/ in quotes
#     (a relative include hides which module it reaches);
#   * a module declares a DEPENDS that none of its files includes;
#   * the files of a module include each other in a cycle: a file's unit is
#     its path without extension (x.h, x.cpp and x.glsl are one unit), and
#     unit a reaches unit b when a file of a includes a file of b.
# Lines inside C++ raw string literals (R"(...)") are text, not includes.
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
  set(used_modules "")
  set(units "")
  foreach(source IN LISTS sources)
    math(EXPR files_checked "${files_checked} + 1")
    file(RELATIVE_PATH rel ${ROOT}/${module} ${source})
    string(REGEX REPLACE "\\.[^./]*$" "" unit "${rel}")
    string(MAKE_C_IDENTIFIER "${unit}" unit_id)
    if(NOT unit IN_LIST units)
      list(APPEND units ${unit})
      set(unit_name_${unit_id} ${unit})
      set(unit_edges_${unit_id} "")
    endif()
    # Whole file first: most files include nothing of interest to a line scan.
    file(STRINGS ${source} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    if(NOT includes)
      continue()
    endif()
    file(STRINGS ${source} lines)
    set(number 0)
    set(raw_end "")  # inside a raw string literal: the text that ends it
    foreach(line IN LISTS lines)
      math(EXPR number "${number} + 1")
      if(raw_end)
        string(FIND "${line}" "${raw_end}" at)
        if(at GREATER_EQUAL 0)
          set(raw_end "")
        endif()
        continue()
      endif()
      if(line MATCHES "R\"([^ ()\\\t\"]*)\\(")
        set(close ")${CMAKE_MATCH_1}\"")
        string(FIND "${line}" "R\"${CMAKE_MATCH_1}(" open_at)
        string(SUBSTRING "${line}" ${open_at} -1 rest)
        string(FIND "${rest}" "${close}" at)
        if(at LESS 0)
          set(raw_end "${close}")
        endif()
      endif()
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*[<\"](stochtex/([A-Za-z0-9_]+)/[^>\"]*)")
        set(header ${CMAKE_MATCH_1})
        set(other ${CMAKE_MATCH_2})
        if(other STREQUAL module)
          string(REGEX REPLACE "^stochtex/[A-Za-z0-9_]+/" "" target_rel "${header}")
          string(REGEX REPLACE "\\.[^./]*$" "" target_unit "${target_rel}")
          if(NOT target_unit STREQUAL unit)
            list(APPEND unit_edges_${unit_id} ${target_unit})
          endif()
        else()
          list(APPEND used_modules ${other})
          if(NOT other IN_LIST allowed)
            problem("${source}:${number}: module ${module} includes ${header}, but may use only ${allowed_text} "
                    "(its DEPENDS in ${module}/CMakeLists.txt, transitively)")
          endif()
        endif()
      elseif(line MATCHES "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\"")
        problem("${source}:${number}: #include \"${CMAKE_MATCH_1}\" is relative: write the module's path "
                "(\"stochtex/<module>/...\") so the checker and readers see which module it reaches")
      endif()
    endforeach()
  endforeach()

  # Each declared dependency is used by some file of the module.
  foreach(dep IN LISTS STOCHTEX_MODULE_DEPENDS_${module})
    if(NOT dep IN_LIST used_modules)
      problem("module ${module}: DEPENDS ${dep}, but none of its files includes stochtex/${dep}/ "
              "(remove it from ${module}/CMakeLists.txt)")
    endif()
  endforeach()

  # No cycle among the module's units: peel off units whose includes all
  # lead to peeled units; whatever remains lies on or before a cycle.
  set(remaining ${units})
  set(progress TRUE)
  while(progress)
    set(progress FALSE)
    set(next "")
    foreach(unit IN LISTS remaining)
      string(MAKE_C_IDENTIFIER "${unit}" unit_id)
      set(blocked FALSE)
      foreach(to IN LISTS unit_edges_${unit_id})
        if(to IN_LIST remaining)
          set(blocked TRUE)
          break()
        endif()
      endforeach()
      if(blocked)
        list(APPEND next ${unit})
      else()
        set(progress TRUE)
      endif()
    endforeach()
    set(remaining ${next})
  endwhile()
  if(remaining)
    # Walk from a remaining unit along remaining units until one repeats: that is a cycle.
    list(GET remaining 0 at)
    set(path "")
    while(NOT at IN_LIST path)
      list(APPEND path ${at})
      string(MAKE_C_IDENTIFIER "${at}" at_id)
      foreach(to IN LISTS unit_edges_${at_id})
        if(to IN_LIST remaining)
          set(at ${to})
          break()
        endif()
      endforeach()
    endwhile()
    list(FIND path ${at} start)
    list(SUBLIST path ${start} -1 cycle)
    list(APPEND cycle ${at})
    string(REPLACE ";" " -> " cycle_text "${cycle}")
    problem("module ${module}: its files include each other in a cycle: ${cycle_text} "
            "(a unit is a file's path without extension)")
  endif()
endforeach()

list(LENGTH STOCHTEX_MODULES module_count)
if(problems GREATER 0)
  message(FATAL_ERROR "module order: ${problems} problem(s) in ${files_checked} files of ${module_count} modules")
endif()
message(STATUS "module order: ${files_checked} files of ${module_count} modules follow their declared DEPENDS")
