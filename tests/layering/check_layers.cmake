# Layering check (docs/design.md §2): every #include of one folder from another
# must be allowed by the table below. Run as a script, so CI needs only CMake:
#
#   cmake -DROOT=<dir holding src/> -P tests/layering/check_layers.cmake
#
# Scans ROOT/src/**/*.{cpp,hpp,glsl} and ROOT/shaders/**/*.glsl. A file belongs
# to its first folder under src/ (or shaders/), methods/<name> counting as its own
# folder. An include "folder/..." or <folder/...> names the folder it depends
# on; a public header <airlight/X.hpp> counts as the folder that owns it
# (PUBLIC_HEADER_OWNER). Includes of anything else (std, glm, GL, same-folder
# names without a slash) are not layering and are skipped.
cmake_minimum_required(VERSION 3.25)

if(NOT DEFINED ROOT OR NOT IS_DIRECTORY "${ROOT}/src")
  message(FATAL_ERROR "layering: pass -DROOT=<dir holding src/>, got '${ROOT}'")
endif()

# The table: what each folder may include besides itself. Dependencies point
# down only; gpu sits on core alone, so the GL layer stays usable without the
# scene; a method reaches others only through the kit. `scene-model` is
# <airlight/scene.hpp>: the scene's types, which optics and geometry compute
# with, apart from the loaders of src/scene/. `contract` is <airlight/method.hpp>
# and <airlight/engine.hpp>: the method contract's types, which every room of
# the kit computes with, implemented by methods/kit/method and methods/kit/engine.
set(BASE gpu reference scene geometry optics core scene-model contract)
set(ALLOW_core        "")
set(ALLOW_optics      core scene-model)
set(ALLOW_geometry    optics core scene-model)
set(ALLOW_scene       core scene-model)
set(ALLOW_reference   geometry optics core scene-model)
set(ALLOW_gpu         core)
set(ALLOW_contract    core scene-model)
# The kit's rooms (docs/design.md §2). Only planes/ reaches the reference (its
# lights' bounds trace rays); the rest sit on the GL layer and below.
set(KIT_BASE gpu scene geometry optics core scene-model contract)
set(ALLOW_methods/kit/frame        ${KIT_BASE})
set(ALLOW_methods/kit/sampling     ${KIT_BASE})
set(ALLOW_methods/kit/engine       methods/kit/frame ${KIT_BASE})
set(ALLOW_methods/kit/resolution   methods/kit/frame ${KIT_BASE})
set(ALLOW_methods/kit/method       methods/kit/resolution methods/kit/engine methods/kit/frame ${KIT_BASE})
set(ALLOW_methods/kit/march        methods/kit/sampling methods/kit/frame ${KIT_BASE})
set(ALLOW_methods/kit/gamma        methods/kit/sampling methods/kit/frame ${KIT_BASE})
set(ALLOW_methods/kit/counting     methods/kit/method methods/kit/gamma methods/kit/sampling methods/kit/frame ${KIT_BASE})
set(ALLOW_methods/kit/light_volume methods/kit/counting methods/kit/method methods/kit/frame ${KIT_BASE})
set(ALLOW_methods/kit/planes       methods/kit/method methods/kit/gamma methods/kit/sampling methods/kit/frame
                                   reference ${KIT_BASE})
set(KIT_ROOMS frame sampling engine resolution method march gamma counting light_volume planes)
list(TRANSFORM KIT_ROOMS PREPEND methods/kit/ OUTPUT_VARIABLE KIT)
# What the tests share, on every room; and a test beside the code it tests
# (*_test.cpp and its *_test_support.{hpp,cpp}, a method's *_quality.cpp) may include it and every room, as the
# suites link the whole kit.
set(ALLOW_methods/kit/testing      ${KIT} ${BASE})
set(ALLOW_test                     methods/kit/testing ${KIT} ${BASE})
# methods/<name>: the kit and everything below it, never another methods/<other>.
set(ALLOW_methods/*   ${KIT} ${BASE})
# The command and the shared library reach methods only through the registry.
set(ALLOW_app         harness ${KIT} ${BASE})
set(ALLOW_lib         ${KIT} ${BASE})
# The differential harness judges methods, through the registry as app does.
set(ALLOW_harness     ${KIT} ${BASE})
# The viewer is a subcommand on app's helpers (scene source, settings); app never includes it.
set(ALLOW_view        app harness ${KIT} ${BASE})

set(PUBLIC_HEADER_OWNER_error    core)
set(PUBLIC_HEADER_OWNER_image    core)
set(PUBLIC_HEADER_OWNER_settings core)
set(PUBLIC_HEADER_OWNER_timing   core)
set(PUBLIC_HEADER_OWNER_box      core)
set(PUBLIC_HEADER_OWNER_export   core)  # AIRLIGHT_API
set(PUBLIC_HEADER_OWNER_scene    scene-model)
set(PUBLIC_HEADER_OWNER_method   contract)
set(PUBLIC_HEADER_OWNER_engine   contract)

set(FOLDERS core optics geometry scene reference gpu methods harness app view lib)

# The arrows are one-way: no row of the table reaches itself through others.
get_cmake_property(variables VARIABLES)
list(FILTER variables INCLUDE REGEX "^ALLOW_")
foreach(row IN LISTS variables)
  string(REGEX REPLACE "^ALLOW_" "" start "${row}")
  set(reached "")
  set(frontier ${${row}})
  while(frontier)
    list(POP_FRONT frontier next)
    if(next IN_LIST reached)
      continue()
    endif()
    list(APPEND reached ${next})
    list(APPEND frontier ${ALLOW_${next}})
  endwhile()
  if(start IN_LIST reached)
    message(FATAL_ERROR "layering: the table's arrows make a cycle through ${start} (${CMAKE_CURRENT_LIST_FILE})")
  endif()
endforeach()

# folder of a path relative to src/ or shaders/ ("methods/raymarch/x.cpp" -> methods/raymarch)
function(folder_of path out)
  string(REPLACE "/" ";" parts "${path}")
  list(LENGTH parts n)
  list(GET parts 0 top)
  if(top STREQUAL "methods" AND n GREATER 2)
    list(GET parts 1 sub)
    set(top "methods/${sub}")
    if(sub STREQUAL "kit" AND n GREATER 3)  # a room of the kit: methods/kit/frame
      list(GET parts 2 room)
      set(top "methods/kit/${room}")
    endif()
  endif()
  set(${out} "${top}" PARENT_SCOPE)
endfunction()

function(rule_of folder out)
  if(folder MATCHES "^methods/" AND NOT folder MATCHES "^methods/kit")
    set(${out} "methods/*" PARENT_SCOPE)
  else()
    set(${out} "${folder}" PARENT_SCOPE)
  endif()
endfunction()

set(files "")
file(GLOB_RECURSE src_files RELATIVE "${ROOT}" "${ROOT}/src/*.cpp" "${ROOT}/src/*.hpp" "${ROOT}/src/*.glsl")
list(APPEND files ${src_files})
if(IS_DIRECTORY "${ROOT}/shaders")
  file(GLOB_RECURSE shader_files RELATIVE "${ROOT}" "${ROOT}/shaders/*.glsl")
  list(APPEND files ${shader_files})
endif()
list(SORT files)

set(violations "")
set(nviolations 0)
set(nincludes 0)
list(LENGTH files nfiles)
foreach(file IN LISTS files)
  string(REGEX REPLACE "^(src|shaders)/" "" rel "${file}")
  folder_of("${rel}" from)
  rule_of("${from}" rule)
  if(NOT DEFINED "ALLOW_${rule}")
    string(APPEND violations "\n  ${file}: folder '${from}' has no row in the table of ${CMAKE_CURRENT_LIST_FILE}")
    math(EXPR nviolations "${nviolations} + 1")
    continue()
  endif()
  set(allowed ${ALLOW_${rule}})
  if(file MATCHES "_(test|quality)\\.cpp$|_test_support\\.(hpp|cpp)$")
    list(APPEND allowed ${ALLOW_test})
  endif()

  # Skip files without includes before numbering their lines.
  file(STRINGS "${ROOT}/${file}" has_include REGEX "^[ \t]*#[ \t]*include")
  if(NOT has_include)
    continue()
  endif()
  file(READ "${ROOT}/${file}" text)
  # Keep ; [ ] and \ from splitting or gluing list elements.
  string(REPLACE "\\" "<backslash>" text "${text}")
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "[" "<lbracket>" text "${text}")
  string(REPLACE "]" "<rbracket>" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(lineno 0)
  foreach(line IN LISTS lines)
    math(EXPR lineno "${lineno} + 1")
    if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*([\"<])([^\">]+)[\">]")
      continue()
    endif()
    set(target "${CMAKE_MATCH_2}")
    if(target MATCHES "^airlight/([a-z_]+)\\.hpp$")
      set(header "${CMAKE_MATCH_1}")
      if(NOT DEFINED "PUBLIC_HEADER_OWNER_${header}")
        continue()  # a public header this table does not know yet: add it above
      endif()
      set(to "${PUBLIC_HEADER_OWNER_${header}}")
    else()
      if(NOT target MATCHES "/")
        continue()
      endif()
      folder_of("${target}" to)
      string(REGEX MATCH "^[^/]+" top "${to}")
      if(NOT top IN_LIST FOLDERS)
        continue()  # not ours (glm/..., nlohmann/..., epoxy/...)
      endif()
    endif()
    math(EXPR nincludes "${nincludes} + 1")
    if(to STREQUAL from OR to IN_LIST allowed)
      continue()
    endif()
    string(REPLACE ";" ", " allowed_text "${allowed}")
    if(allowed_text STREQUAL "")
      set(allowed_text "no other folder")
    else()
      set(allowed_text "only ${allowed_text}")
    endif()
    if(from MATCHES "^methods/" AND to MATCHES "^methods/" AND NOT to MATCHES "^methods/kit")
      set(why "a method never includes another method's folder (${rule} may include ${allowed_text})")
    else()
      set(why "${from} may include ${allowed_text}")
    endif()
    string(REPLACE "<semicolon>" ";" shown "${line}")
    string(REPLACE "<lbracket>" "[" shown "${shown}")
    string(REPLACE "<rbracket>" "]" shown "${shown}")
    string(REPLACE "<backslash>" "\\" shown "${shown}")
    string(STRIP "${shown}" shown)
    string(APPEND violations "\n  ${file}:${lineno}: ${shown}: ${from} -> ${to} breaks the rule: ${why}")
    math(EXPR nviolations "${nviolations} + 1")
  endforeach()
endforeach()

if(nviolations GREATER 0)
  message(FATAL_ERROR "layering: ${nviolations} violation(s) of the dependency table in "
                      "${CMAKE_CURRENT_LIST_FILE} (docs/design.md §2):${violations}")
endif()
message(STATUS "layering: ${nfiles} files, ${nincludes} includes between folders, all allowed")
