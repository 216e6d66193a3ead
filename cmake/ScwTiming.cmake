# SPDX-License-Identifier: Apache-2.0
# The timing budget of one path of logic, in ps, read from host/synth/timing.hpp (kStaBudgetPs),
# the one place it is written (docs/timing.md): the rtl.yosys.* guard and the `scw synth` test
# use this, so they cannot disagree with `scw synth`'s table.
function(scw_sta_budget out_var)
  set(_name kStaBudgetPs)
  get_filename_component(_root "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/.." ABSOLUTE)
  file(STRINGS "${_root}/host/synth/timing.hpp" _line REGEX "${_name} = [0-9]+")
  string(REGEX REPLACE ".*${_name} = ([0-9]+).*" "\\1" _ps "${_line}")
  if(NOT _ps MATCHES "^[0-9]+$")
    message(FATAL_ERROR "cannot read ${_name} from ${_root}/host/synth/timing.hpp")
  endif()
  set(${out_var} ${_ps} PARENT_SCOPE)
endfunction()
