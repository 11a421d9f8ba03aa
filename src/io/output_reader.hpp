// The `output` section of a case file (docs/case-file.md): where results go, which files, the
// depths at which VTU files are written and how they are encoded; and the reading of a list of
// depths (path.depths, output.at).
#pragma once

#include <string>
#include <vector>

#include "io/vtu_writer.hpp"

namespace si {

class MapReader;  // io/yaml_reader.hpp

enum class OutputFormat { kCsv, kJson, kVtu };

struct OutputSpec {
  std::string dir = "results/";
  int vtu_every = 10;  // write a VTU file every n converged steps; 0 = never
  std::vector<OutputFormat> formats{OutputFormat::kCsv, OutputFormat::kJson, OutputFormat::kVtu};
  std::vector<double> at;  // depths (mm, increasing) with a VTU file; the path lands on them
  VtuEncoding vtu_encoding = VtuEncoding::kAuto;
  bool mirror = false;  // a quarter model's VTU files show the full shape
};

// The optional `output` section of `top`; depth_max bounds output.at; output.mirror needs a
// quarter model.
OutputSpec read_output(const MapReader& top, double depth_max, bool quarter);

// map[key]: a non-empty list of lengths, strictly increasing, each in (0, depth_max]; errors name
// the entry (key[i]), its value and line.
std::vector<double> read_depth_list(const MapReader& map, const std::string& key, double depth_max);

}  // namespace si
