#pragma once
// Reading back a results folder in tests: summary.json with nlohmann/json, VTU files with meshio
// (an independent reader, through tests/support/read_vtu.py and Debian's /usr/bin/python3).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace bimrock::testing {

inline nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in)
    throw std::runtime_error("cannot read " + file.string());
  return nlohmann::json::parse(in);
}

/// {"points": n, "cells": {type: count}, "cell_data": {name: [[...] per cell]}, "point_data": ...}
inline nlohmann::json read_vtu_with_meshio(const std::filesystem::path& vtu) {
  const std::string cmd = std::string(BIMROCK_PYTHON) + " '" + BIMROCK_SOURCE_DIR +
                          "/tests/support/read_vtu.py' '" + vtu.string() + "'";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  if (!pipe)
    throw std::runtime_error("cannot run " + cmd);
  std::string text;
  char buffer[65536];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe.get())) > 0;)
    text.append(buffer, n);
  return nlohmann::json::parse(text);
}

}  // namespace bimrock::testing
