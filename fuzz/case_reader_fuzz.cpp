// libFuzzer target: the case reader, YAML text -> case spec (io/case_reader.hpp). Every input
// must end in a case or in one InputError naming the file; a crash, any other exception (which
// the command would report as an internal error), a hang or unbounded memory is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include <bimrock/io/case_reader.hpp>
#include <bimrock/model/errors.hpp>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    static_cast<void>(bimrock::read_case_string(text, bimrock::fuzz::case_name()));
  } catch (const bimrock::InputError& e) {
    bimrock::fuzz::expect_located(e);
  }
  return 0;
}
