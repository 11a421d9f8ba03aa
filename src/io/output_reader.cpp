#include "io/output_reader.hpp"

#include "core/error.hpp"
#include "core/units.hpp"
#include "io/spellings.hpp"
#include "io/yaml_reader.hpp"

namespace si {
namespace {

const Choices<OutputFormat> kFormats{
    {"csv", OutputFormat::kCsv}, {"json", OutputFormat::kJson}, {"vtu", OutputFormat::kVtu}};
const Choices<VtuEncoding> kEncodings{
    {"auto", VtuEncoding::kAuto}, {"ascii", VtuEncoding::kAscii}, {"binary", VtuEncoding::kBinary}};

// The entry i of a list under `list_where`, for messages.
Where entry_where(const Where& list_where, const YAML::Node& entry, std::size_t i) {
  return Where{list_where.file, list_where.key + "[" + std::to_string(i) + "]", text_of(entry),
               line_of(entry)};
}

std::vector<OutputFormat> read_formats(const MapReader& map) {
  const YAML::Node list = map.at("formats");
  const Where list_where = map.where("formats");
  if (!list.IsSequence()) throw_input("expected a list such as [csv, vtu]", list_where);
  std::vector<OutputFormat> formats;
  for (std::size_t i = 0; i < list.size(); ++i)
    formats.push_back(read_choice(list[i], entry_where(list_where, list[i], i), kFormats));
  return formats;
}

}  // namespace

std::vector<double> read_depth_list(const MapReader& map, const std::string& key,
                                    double depth_max) {
  const YAML::Node list = map.at(key);
  const Where list_where = map.where(key);
  if (!list.IsSequence() || list.size() == 0)
    throw_input("expected a non-empty list of depths", list_where);
  std::vector<double> depths;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Where w = entry_where(list_where, list[i], i);
    const double d = read_quantity(list[i], w, Dimension::kLength);
    if (!(d > 0.0) || d > depth_max)
      throw_input("each depth must lie in (0, depth_max = " +
                      format_quantity(depth_max, Dimension::kLength) + "]",
                  w);
    if (!depths.empty() && d <= depths.back()) throw_input("depths must increase strictly", w);
    depths.push_back(d);
  }
  return depths;
}

OutputSpec read_output(const MapReader& top, double depth_max, bool quarter) {
  OutputSpec output;
  if (!top.has("output")) return output;
  const MapReader map(top.at("output"), top.where("output"));
  map.allow_only({"dir", "vtu_every", "formats", "at", "vtu_encoding", "mirror"});
  output.dir = map.scalar_or("dir", output.dir);
  output.vtu_every = map.integer_or("vtu_every", output.vtu_every);
  if (output.vtu_every < 0)
    throw_input("must be >= 0 (0 writes VTU files only at output.at)", map.where("vtu_every"));
  if (map.has("formats")) output.formats = read_formats(map);
  if (map.has("at")) output.at = read_depth_list(map, "at", depth_max);
  output.vtu_encoding = map.choice_or("vtu_encoding", kEncodings, output.vtu_encoding);
  output.mirror = map.choice_or("mirror", boolean_spellings(), output.mirror);
  if (output.mirror && !quarter)
    throw_input("mirror needs a quarter model (mesh.symmetry: quarter)", map.where("mirror"));
  return output;
}

}  // namespace si
