#pragma once
// The body shared by the libFuzzer targets of fuzz/ (docs/robustness.md): feed the bytes to one
// reader of io/ as JSON text. Bad input must end in an InvalidInput (the command's exit 2); any
// other exception, a crash or a sanitizer report is a finding. The replay test (fuzz/replay.cpp)
// runs the same body over the corpus and the regression files without libFuzzer.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "bezierpde/core/errors.h"

namespace bpde::fuzz {

template <class Reader>
int run_reader(const uint8_t* data, size_t size, Reader&& read) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    read(text);
  } catch (const InvalidInput&) {
    // bad input, refused: the contract
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: not an InvalidInput: %s\n", e.what());
    std::abort();
  }
  return 0;
}

}  // namespace bpde::fuzz
