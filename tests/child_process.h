// A test's child process: this same executable started again with posix_spawn (fork and exec
// as one call), so the child is a real, separate process. Qt's QProcess is not used on purpose:
// it starts its child with clone(CLONE_VM | CLONE_VFORK), and ThreadSanitizer, whose state the
// child shares until exec, then believes the parent forked while multi-threaded and kills it at
// its next new thread ("starting new threads after multi-threaded fork is not supported").
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace inlay::test {

class ChildProcess {
 public:
  ChildProcess() = default;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ~ChildProcess() {  // never leaves a child behind, even when a check failed half-way
    if (pid_ > 0 && !status_) {
      ::kill(pid_, SIGKILL);
      waitFor(std::chrono::seconds(10));
    }
    if (out_ >= 0) ::close(out_);
  }

  // Starts this executable with `args` and the environment plus `env` ("NAME=value" each).
  // With `captureStdout` the child's standard output comes to readLine() through a pipe; its
  // standard error stays the test's. False when the child could not be started.
  bool start(const std::vector<std::string>& args, const std::vector<std::string>& env,
             bool captureStdout) {
    const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
    std::vector<std::string> argStore = {exe};
    argStore.insert(argStore.end(), args.begin(), args.end());
    std::vector<char*> argv, envp;
    for (std::string& a : argStore) argv.push_back(a.data());
    argv.push_back(nullptr);
    for (char** e = environ; *e; ++e) envp.push_back(*e);
    std::vector<std::string> envStore = env;
    for (std::string& e : envStore) envp.push_back(e.data());
    envp.push_back(nullptr);

    int pipeFds[2] = {-1, -1};
    if (captureStdout && ::pipe2(pipeFds, O_CLOEXEC) != 0) return false;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (captureStdout) posix_spawn_file_actions_adddup2(&actions, pipeFds[1], STDOUT_FILENO);
    const int rc = posix_spawn(&pid_, exe.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (captureStdout) {
      ::close(pipeFds[1]);
      out_ = pipeFds[0];
    }
    if (rc != 0) pid_ = -1;
    return rc == 0;
  }

  pid_t pid() const { return pid_; }

  // The child's next line of output (without '\n'); what came before the deadline or the end
  // of its output otherwise.
  std::string readLine(std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    std::string line;
    char c = 0;
    while (out_ >= 0) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      pollfd p = {out_, POLLIN, 0};
      if (left.count() <= 0 || ::poll(&p, 1, int(left.count())) <= 0) break;
      if (::read(out_, &c, 1) != 1 || c == '\n') break;
      line += c;
    }
    return line;
  }

  // "exit code N", "killed by signal N" or "still running", for a test's failure message.
  static std::string describe(std::optional<int> status) {
    if (!status) return "still running";
    if (WIFEXITED(*status)) return "exit code " + std::to_string(WEXITSTATUS(*status));
    if (WIFSIGNALED(*status)) return "killed by signal " + std::to_string(WTERMSIG(*status));
    return "wait status " + std::to_string(*status);
  }

  bool kill(int signal = SIGKILL) { return pid_ > 0 && ::kill(pid_, signal) == 0; }

  // The child's wait status (see waitpid) once it has ended; nullopt if it still runs at the
  // deadline.
  std::optional<int> waitFor(std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!status_ && pid_ > 0) {
      int status = 0;
      const pid_t r = ::waitpid(pid_, &status, WNOHANG);
      if (r == pid_ || r < 0) {  // -1: not our child any more (neither exited nor signalled)
        status_ = r == pid_ ? status : -1;
        break;
      }
      if (std::chrono::steady_clock::now() > end) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return status_;
  }

 private:
  pid_t pid_ = -1;
  int out_ = -1;
  std::optional<int> status_;
};

}  // namespace inlay::test
