#include "app/calibrate_command.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/interrupt_signals.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "io/calibration_report.hpp"
#include "io/case_calibration.hpp"
#include "io/output_directory.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

int run_calibrate_command(const CalibrateCommandOptions& o, std::ostream& out, std::ostream& err) {
  const CaseCalibrationInput input{o.case_file, read_text(o.case_file), o.params, o.settings};
  const CaseCalibration calibration(
      input,
      [&](int min_points) {
        return read_measured_curve(o.data_file, o.x_column, o.y_column, min_points);
      },
      err);
  const fs::path dir =
      o.out_dir.empty()
          ? fs::path("results") / (fs::path(o.case_file).stem().string() + "_calibration")
          : fs::path(o.out_dir);
  prepare_output_directory(dir, Where{"command line", "--out", dir.string(), 0});

  err << calibration.header_line() << "\n";
  fit::CalibrationResult r;
  {
    InterruptGuard guard;
    r = calibration.run(
        [&](const fit::CalibrationProgress& p) {
          err << calibration.progress_line(p) << std::endl;
          return !interrupted();
        },
        [] { return !interrupted(); });
  }
  if (r.status == fit::CalibrationStatus::kInterrupted)
    err << "calibrate: interrupted (" << interrupt_name() << ")\n";

  const CalibrationContext& context = calibration.context();
  write_file_atomically((dir / "calibration.json").string(),
                        calibration_json(context, r).dump(2) + "\n");
  write_file_atomically((dir / "calibration_curve.csv").string(),
                        calibration_curve_csv(context, r));
  if (r.parameters.size() == static_cast<Eigen::Index>(o.params.size()))
    write_file_atomically((dir / "calibrated_case.yaml").string(),
                          calibration.case_yaml(r.parameters));
  out << calibration_table(context, r);
  err << "wrote " << (dir / "calibration.json").string()
      << ", calibration_curve.csv and calibrated_case.yaml\n";
  return r.status == fit::CalibrationStatus::kConverged ? 0 : 1;
}

}  // namespace si
