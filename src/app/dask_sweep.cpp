#include "app/dask_sweep.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <thread>
#include <vector>

#include "app/interrupt_signals.hpp"
#include "app/sweep_cases.hpp"
#include "core/error.hpp"
#include "io/output_directory.hpp"
#include "io/output_lock.hpp"

extern char** environ;

namespace si {
namespace {

namespace fs = std::filesystem;

// The connect timeout for the scheduler, seconds: an address nobody listens on is an error
// after this long, not a hang.
constexpr int kConnectTimeoutSeconds = 10;

// Runs the module's command line, turning an import failure into the CLI's error and exit 2.
constexpr const char* kBootstrap =
    "import sys\n"
    "try:\n"
    "    from shellindent import sweep_cli\n"
    "except ImportError as e:\n"
    "    sys.stderr.write('shellindent: error: command line: --scheduler = ' + repr(sys.argv[1]) "
    "+\n"
    "        ': the Python module shellindent cannot be imported by ' + sys.executable +\n"
    "        ' (' + str(e) + '); build it (CMake option SHELLINDENT_PYTHON) or install it '\n"
    "        '(cmake --install BUILD --component python), or set SHELLINDENT_PYTHON\\n')\n"
    "    sys.exit(2)\n"
    "sys.exit(sweep_cli.main(sys.argv[1:]))\n";

std::string python_executable() {
  const char* chosen = std::getenv("SHELLINDENT_PYTHON");
  if (chosen && *chosen) return chosen;
#ifdef SHELLINDENT_PYTHON_EXECUTABLE
  return SHELLINDENT_PYTHON_EXECUTABLE;
#else
  return "/usr/bin/python3";
#endif
}

// The environment of the child: PYTHONPATH with the build tree's module first, if it is there.
std::vector<std::string> child_environment() {
  std::vector<std::string> env;
  std::string python_path;
#ifdef SHELLINDENT_PYTHON_BUILD_DIR
  if (fs::exists(fs::path(SHELLINDENT_PYTHON_BUILD_DIR) / "shellindent" / "__init__.py"))
    python_path = SHELLINDENT_PYTHON_BUILD_DIR;
#endif
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    if (entry.rfind("PYTHONPATH=", 0) == 0) {
      const std::string inherited = entry.substr(11);
      if (!inherited.empty()) python_path += (python_path.empty() ? "" : ":") + inherited;
    } else {
      env.push_back(entry);
    }
  }
  if (!python_path.empty()) env.push_back("PYTHONPATH=" + python_path);
  return env;
}

pid_t spawn_python(const std::vector<std::string>& args_in) {
  std::vector<std::string> args = args_in;
  std::vector<std::string> env = child_environment();
  std::vector<char*> argv, envp;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, args[0].c_str(), nullptr, nullptr, argv.data(), envp.data());
  if (rc != 0)
    throw_input("cannot start the Python interpreter " + args[0] + " (" + std::strerror(rc) +
                    "); set SHELLINDENT_PYTHON to one that has the shellindent module",
                Where{"command line", "--scheduler", args[3], 0});
  return pid;
}

// Waits for the child; a Ctrl-C or SIGTERM here is passed on as SIGINT (KeyboardInterrupt).
int wait_for(pid_t pid) {
  bool forwarded = false;
  while (true) {
    int status = 0;
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
    if (done < 0 && errno != EINTR) return 1;
    if (interrupted() && !forwarded) {
      kill(pid, SIGINT);
      forwarded = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

}  // namespace

int run_dask_sweep(const SweepCommandOptions& o, std::ostream&, std::ostream& err) {
  const SweepCases s = load_sweep_cases(o.study_file, o.quick);  // bad input: here, exit 2
  const fs::path root = sweep_root(o, s.study);
  const Where root_where = sweep_root_where(o, s.study);
  const bool existed = fs::exists(root);
  prepare_output_directory(root, root_where);
  int code = 2;
  std::exception_ptr failure;  // the interpreter could not be started
  {
    const OutputLock lock(root, root_where);
    err << "sweep: " << o.study_file << ": " << s.cases.size() << " case(s)"
        << (o.quick ? " (--quick)" : "") << " on the Dask cluster at " << o.scheduler << std::endl;
    std::vector<std::string> args{
        python_executable(), "-c",         kBootstrap,
        o.scheduler,         o.study_file, "--out",
        root.string(),       "--timeout",  std::to_string(kConnectTimeoutSeconds)};
    if (o.quick) args.push_back("--quick");
    const InterruptGuard guard;
    try {
      code = wait_for(spawn_python(args));
    } catch (const Error&) {
      failure = std::current_exception();
    }
  }
  // Bad input (no interpreter, no module, no scheduler): nothing was written, leave nothing.
  std::error_code ec;
  if ((failure || code == 2) && !existed) fs::remove(root, ec);  // only if still empty
  if (failure) std::rethrow_exception(failure);
  return code;
}

}  // namespace si
