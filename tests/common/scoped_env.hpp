// SPDX-License-Identifier: Apache-2.0
// An environment variable set for one scope, for the tests of settings scw reads from the
// environment (SCW_READER_SECONDS, SCW_FST_DIR, SCW_FST_WINDOW).
#pragma once

#include <cstdlib>
#include <string>

namespace scw::test {

/// Sets `name` to `value` and unsets it when the scope ends, also when a check throws, so no
/// later test in the process sees it.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) { set(value); }
  ~ScopedEnv() { ::unsetenv(name_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

  void set(const std::string& value) { ::setenv(name_, value.c_str(), 1); }

 private:
  const char* name_;
};

}  // namespace scw::test
