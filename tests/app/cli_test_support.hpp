// Running the `shellindent` executable from a test: exit code and output, fresh temp dirs.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "test_paths.hpp"

namespace si::testing {

namespace fs = std::filesystem;

struct CliResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline CliResult run_cli(const std::string& args) {
  const std::string cmd = std::string("'") + SHELLINDENT_EXE + "' " + args + " 2>&1";
  CliResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf{};
  size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// One directory per test and per build tree (hash of the executable's path): ctest runs of
// several checkouts on one machine must not share (and delete) each other's files.
inline fs::path fresh_dir(const std::string& name) {
  const std::string tree = std::to_string(std::hash<std::string>{}(SHELLINDENT_EXE) % 1000000);
  const fs::path dir = fs::temp_directory_path() / ("shellindent_cli_" + tree + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Writes `text` as DIR/case.yaml and returns the path.
inline fs::path write_case(const fs::path& dir, const std::string& text) {
  const fs::path path = dir / "case.yaml";
  std::ofstream(path) << text;
  return path;
}

inline std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace si::testing
