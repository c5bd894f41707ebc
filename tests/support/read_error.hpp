#pragma once
// The message of the InputError that reading a case text throws ("" if it reads).
#include <string>

#include <bimrock/io/case_reader.hpp>

namespace bimrock::testing {

inline std::string read_error_of(const std::string& text) {
  try {
    read_case_string(text, "case.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace bimrock::testing
