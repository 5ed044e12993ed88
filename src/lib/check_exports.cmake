# ctest library_exports: libairlight's dynamic symbols are the public API
# (include/airlight/, AIRLIGHT_API) and nothing else. Run as
#   cmake -DLIBRARY=libairlight.so -DNM=nm -P check_exports.cmake
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND ${NM} -D --defined-only -C ${LIBRARY} OUTPUT_VARIABLE symbols RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "${NM} -D ${LIBRARY} failed")
endif()
string(STRIP "${symbols}" symbols)
string(REPLACE "\n" ";" lines "${symbols}")
list(LENGTH lines count)
message(STATUS "${count} defined dynamic symbols")

# Present: the entry points, and the type information a program needs to catch
# airlight's errors by type and to hold a Method.
foreach(wanted IN ITEMS
    "airlight::find_method(" "airlight::registered_methods()" "airlight::use_current_gl_context()"
    "airlight::builtin_scene(" "airlight::load_scene(" "airlight::Settings::set("
    "typeinfo for airlight::InputError" "typeinfo for airlight::Failure" "typeinfo for airlight::OutOfMemory"
    "typeinfo for airlight::Method" "vtable for airlight::Method")
  string(FIND "${symbols}" "${wanted}" at)
  if(at EQUAL -1)
    message(SEND_ERROR "not exported: ${wanted}")
  endif()
endforeach()

# Absent: airlight's layers (a namespace below airlight::, lower case: kit::,
# gpu::, geometry::, optics::, reference::, methods:: ...), and what the
# library uses of Embree, oneTBB, the GL loader and the header-only libraries.
foreach(line IN LISTS lines)
  if(line MATCHES "airlight::[a-z_]+::|[ :]rtc[A-Z]|tbb::|epoxy|nlohmann::|tinygltf::|tinyobj::|glm::")
    message(SEND_ERROR "exported: ${line}")
  endif()
endforeach()
