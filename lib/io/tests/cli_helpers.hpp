// Running the built `dda` executable from the tests: its exit code, its
// messages, the files it wrote; a run that is sent a signal while it runs.
#pragma once
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace dda::io::test {

namespace fs = std::filesystem;

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A fresh, empty directory's path under the tests' scratch directory (not created).
inline std::string scratch(const std::string& name) {
  const fs::path p = fs::path(DDA_IO_TEST_TMP) / "runs" / name;
  fs::remove_all(p);
  fs::create_directories(p.parent_path());
  return p.string();
}

// Starts `dda <args>` with stdout and stderr to `log` (niceness added to
// its scheduling priority's nice value); its process id.
inline pid_t start_cli(const std::vector<std::string>& args, const std::string& log, int niceness = 0) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (niceness != 0) ::setpriority(PRIO_PROCESS, 0, niceness);  // best effort: it only helps timing
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
    }
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(DDA_CLI_PATH));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(DDA_CLI_PATH, argv.data());
    ::_exit(127);
  }
  return pid;
}

// Its exit code, or 128 + the signal that ended it.
inline int wait_cli(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

inline int run_cli(const std::vector<std::string>& args, const std::string& log) {
  return wait_cli(start_cli(args, log));
}

// Runs `dda <args>` and sends it `signal` after `delay` s (if it still runs).
inline int run_cli_signalled(const std::vector<std::string>& args, const std::string& log, double delay, int signal) {
  const pid_t pid = start_cli(args, log);
  std::this_thread::sleep_for(std::chrono::duration<double>(delay));
  ::kill(pid, signal);
  return wait_cli(pid);
}

// Starts `dda <args>` (at the lowest scheduling priority), waits until
// `file` exists and `delay` s more, then sends `signal`; its exit code (the
// run's own if it ended first). The low priority makes this process, which
// polls every 200 us, the first to run when the file appears, on a machine
// busy with other work too: a run that ends a few ms after writing the file
// is still caught.
inline int signalled_when(const std::vector<std::string>& args, const std::string& log, const std::string& file,
                          int signal, double delay = 0.0) {
  const pid_t pid = start_cli(args, log, 19);
  for (;;) {
    if (fs::exists(file)) {
      std::this_thread::sleep_for(std::chrono::duration<double>(delay));
      ::kill(pid, signal);
      break;
    }
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return wait_cli(pid);
}

// Every regular file under `dir`: relative path -> bytes.
inline std::map<std::string, std::string> files_of(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = slurp(e.path().string());
  return out;
}

}  // namespace dda::io::test
