# SPDX-License-Identifier: Apache-2.0
# [rtl] scw_warning against the warning model clock for clock, at the two builds of
# warning/test_warning_rtl.cpp (which static_asserts the same parameters), and its square root
# against isqrt_round and its distance rule against rule_disparity.
scw_rtl_model_library(scw_test_rtl_warning)
scw_verilate(scw_test_rtl_warning TOP scw_warning PREFIX Vwarning_a STAGE warning
             PARAMS MaxDisparityPx=64)
scw_verilate(scw_test_rtl_warning TOP scw_warning PREFIX Vwarning_b STAGE warning
             PARAMS MaxDisparityPx=32)
# The square root alone, at every rounding boundary (isqrt_round).
scw_verilate(scw_test_rtl_warning TOP scw_warning_sqrt PREFIX Vwarning_sqrt STAGE warning
             FILES scw_warning_sqrt.sv)
# The distance rule alone, bit for bit against rule_disparity.
scw_verilate(scw_test_rtl_warning TOP scw_warning_rule PREFIX Vwarning_rule STAGE warning
             FILES scw_warning_rule.sv scw_warning_sqrt.sv scw_warning_delay.sv)
add_executable(test_warning_rtl warning/test_warning_rtl.cpp)
target_link_libraries(test_warning_rtl
                      PRIVATE scw_test_main scw::sim scw::host scw_test_rtl_warning)
scw_warnings(test_warning_rtl)
scw_discover_tests(test_warning_rtl TEST_PREFIX "warning:")
