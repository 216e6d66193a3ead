# SPDX-License-Identifier: Apache-2.0
# cmake -DNM=nm -DOBJECTS="a.o;b.o" -P check_synthesis_objects.cmake
# Fails if an object of a C-synthesis top (hls/tops, compiled with __SYNTHESIS__ and
# -fno-exceptions) references the heap or the exception runtime: what an HLS tool cannot map to
# hardware. Function-local statics' guards (__cxa_guard_*) and memset/memcpy are allowed: the tool
# maps a static kernel to registers and RAMs, and the copies to loops.
if(NOT OBJECTS)
  message(FATAL_ERROR "check_synthesis_objects: no objects given (-DOBJECTS=...)")
endif()
set(forbidden "operator new|operator delete|malloc|calloc|realloc|[^_]free$|__cxa_throw|__cxa_allocate_exception|__cxa_rethrow|std::__throw_|std::__cxx11::basic_string|std::vector")
set(bad "")
foreach(obj IN LISTS OBJECTS)
  execute_process(COMMAND ${NM} -uC ${obj} OUTPUT_VARIABLE syms RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "check_synthesis_objects: ${NM} failed on ${obj}")
  endif()
  string(REPLACE "\n" ";" lines "${syms}")
  foreach(line IN LISTS lines)
    if(line MATCHES "(${forbidden})")
      get_filename_component(name ${obj} NAME)
      string(STRIP "${line}" line)
      list(APPEND bad "${name}: ${line}")
    endif()
  endforeach()
  message(STATUS "${obj}: no heap, no throw")
endforeach()
if(bad)
  list(JOIN bad "\n  " text)
  message(FATAL_ERROR "C-synthesis tops reference the heap or exceptions:\n  ${text}\n"
                      "keep host-only code under #ifndef __SYNTHESIS__ (docs/hls.md)")
endif()
