// The VTU files of an indentation run and their ParaView collection path.pvd: a file every
// output.vtu_every points (path_NNNN.vtu), at each depth of output.at (the path lands on them),
// at each located event (event_NN.vtu; a stability change's with its critical mode) and at the
// last point. Points at the reference positions, the displacement as a point field
// (io/vtu_writer.hpp); output.vtu_encoding and output.mirror say how they are written.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "analysis/indentation_run.hpp"
#include "io/output_reader.hpp"

namespace si {

class PathVtus {
 public:
  // `enabled`: output.formats has vtu.
  PathVtus(std::filesystem::path dir, const OutputSpec& output, const IndentationSetup& setup,
           bool enabled);

  // A converged point: its file if its index is a multiple of vtu_every or its depth is one of
  // output.at (within 1e-9 of depth_max: the continuation lands on them to round-off).
  void at_point(const IndentationSetup& setup, const PathPoint& p, const cont::Vector& z);

  // After the run: the last point's file (if not yet written) and the located events' files.
  // Returns the number of event files.
  int after_run(IndentationSetup& setup, const PathResult& r);

  bool empty() const { return frames_.empty(); }
  std::size_t size() const { return frames_.size(); }

  // path.pvd: the files in depth order, each once (a file at a depth already listed is left
  // out; ParaView shows one frame per time step).
  std::string pvd() const;

  // The files written so far, kept in the checkpoint for --resume.
  nlohmann::json record() const;
  void restore(const nlohmann::json& frames);

 private:
  void write(const std::string& name, const IndentationSetup& setup, const IndentationState& st,
             const cont::Vector& z, const Eigen::MatrixXd* mode = nullptr);

  std::filesystem::path dir_;
  OutputSpec output_;
  VtuFormat format_;
  bool enabled_;
  std::vector<std::pair<double, std::string>> frames_;  // depth, file name; in writing order
};

}  // namespace si
