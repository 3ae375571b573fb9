// inkray-render and inkray-merge killed (SIGKILL) at many moments, renames included: once
// the next writer into the folder has run, no temporary or journal is left, and the image
// and AOVs on disk are always of one run (docs/architecture.md, "Files written").
#include "tests/support/file_helpers.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace inkray {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using testing::Names;
using testing::read_file;
using testing::ScratchFolder;

const std::string kRender = std::string(INKRAY_BINARY_DIR) + "/bin/inkray-render";
const std::string kMerge = std::string(INKRAY_BINARY_DIR) + "/bin/inkray-merge";
const std::string kCornell = std::string(INKRAY_SOURCE_DIR) + "/scenes/cornell.json";
constexpr char kDelayHook[] = "INKRAY_TEST_COMMIT_DELAY_MS";

// Starts args[0] with its output discarded and, when delay_ms > 0, the test hook that makes
// every rename of a staged file wait that long (core/io/atomic_file.h).
pid_t start(const std::vector<std::string>& args, int delay_ms) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::vector<std::string> env_text;
  for (char** e = environ; *e; ++e)
    if (!std::string_view(*e).starts_with(std::string(kDelayHook) + "=")) env_text.push_back(*e);
  if (delay_ms > 0) env_text.push_back(std::string(kDelayHook) + "=" + std::to_string(delay_ms));
  std::vector<char*> envp;
  for (std::string& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(127);
  }
  return child;
}

int finish(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int run(const std::vector<std::string>& args) { return finish(start(args, 0)); }

void kill_and_reap(pid_t pid) {
  ::kill(pid, SIGKILL);  // a process that already ended is a zombie until reaped: no other gets the signal
  finish(pid);
}

bool has_ended(pid_t pid) {
  siginfo_t info{};
  return ::waitid(P_PID, id_t(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid;
}

// What killed writers leave: temporaries and journals.
Names debris(const fs::path& dir) {
  Names names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.find(".inkray-tmp-") != std::string::npos || name.find(".inkray-journal") != std::string::npos)
      names.push_back(name);
  }
  return names;
}

Names entries(const fs::path& dir) {
  Names names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Waits until a name in `dir` contains `part`; false when `pid` ended first.
bool wait_for_entry(pid_t pid, const fs::path& dir, const std::string& part) {
  const auto give_up = Clock::now() + std::chrono::seconds(30);
  while (Clock::now() < give_up) {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().find(part) != std::string::npos) return true;
    if (has_ended(pid)) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return false;
}

void sleep_ms(double ms) { std::this_thread::sleep_for(std::chrono::microseconds(long(ms * 1000.0))); }

double milliseconds_of(const std::vector<std::string>& args) {
  const auto t0 = Clock::now();
  EXPECT_EQ(run(args), 0);
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::vector<std::string> render_args(const fs::path& dir, int seed) {
  return {kRender,
          kCornell,
          "--width",
          "32",
          "--height",
          "32",
          "--spp",
          "16",
          "--threads",
          "2",
          "-q",
          "--seed",
          std::to_string(seed),
          "-o",
          (dir / "image.png").string(),
          "--aov",
          "depth=" + (dir / "depth.exr").string(),
          "--aov",
          "normal=" + (dir / "normal.png").string()};
}

struct Files {
  std::string image, depth, normal;
  bool operator==(const Files&) const = default;
};

Files read_set(const fs::path& dir) {
  return {read_file(dir / "image.png"), read_file(dir / "depth.exr"), read_file(dir / "normal.png")};
}

// Kills fall at spread moments of a run, half of them while the renames are under way
// (found by the journal appearing, the renames slowed by the test hook); then another
// writer into the folder (--decide-lines) runs. The set on disk is then the one from
// before the killed run or, whenever its journal was written, the killed run's whole set.
TEST(OutputKill, TheImageAndItsAovsOnDiskAreAlwaysOfOneRun) {
  ScratchFolder dir, references;
  fs::create_directory(dir / "out");
  const fs::path out = dir / "out";
  const double run_ms = milliseconds_of(render_args(out, 0));
  Files current = read_set(out);
  const auto reference = [&](int seed) {
    EXPECT_EQ(run(render_args(references.path(), seed)), 0);
    return read_set(references.path());
  };
  const std::vector<std::string> other_writer = {kRender, kCornell,         "--width",
                                                 "32",    "--height",       "32",
                                                 "-q",    "--decide-lines", (out / "lines.bin").string()};
  int journals_completed = 0, changed = 0;
  constexpr int kKills = 30;
  for (int i = 1; i <= kKills; ++i) {
    SCOPED_TRACE("kill " + std::to_string(i));
    const bool in_renames = i % 2 == 0;
    const int step = (i / 2) % 5;
    const pid_t pid = start(render_args(out, i), in_renames ? 25 : 0);
    if (in_renames) {
      // Once the last file is staged: 3 renames, 25 ms apart, killed before the first,
      // after one, two or all of them.
      if (wait_for_entry(pid, out, ".normal.png.inkray-tmp-")) sleep_ms(10.0 + 25.0 * step);
    } else {
      sleep_ms(run_ms * (0.1 + 0.25 * step));
    }
    kill_and_reap(pid);
    const bool journal_left = fs::exists(out / ".image.png.inkray-journal");
    ASSERT_EQ(run(other_writer), 0);
    EXPECT_EQ(debris(dir.path()), Names{});
    const Files on_disk = read_set(out);
    if (on_disk == current && !journal_left) continue;
    const Files killed_run = reference(i);
    ASSERT_NE(killed_run.image, current.image) << "seed " << i << " renders the image of the seed before";
    EXPECT_TRUE(on_disk == killed_run) << "the files on disk are of different runs";
    ++changed;
    journals_completed += journal_left;
    current = on_disk;
  }
  // Kills landed between renames and the killed runs' sets were completed.
  EXPECT_GE(journals_completed, 3);
  std::printf("[          ] %d kills, %d left a new set, %d of them a journal completed by the next writer\n",
              kKills, changed, journals_completed);
}

struct Writer {
  std::string name;
  std::vector<std::string> args;
  Names files;  // what the folder holds once the writer has run to its end
};

// Every writer, killed over and over (half the kills while a temporary waits for its
// rename), and run again to its end each time: nothing is left but its files.
TEST(OutputKill, EveryWriterLeavesNoDebris) {
  ScratchFolder dir;
  fs::create_directory(dir / "in");
  fs::create_directory(dir / "out");
  const fs::path in = dir / "in", out = dir / "out";
  const std::vector<std::string> base = {kRender, kCornell, "--width", "32", "--height", "32", "-q"};
  const auto with = [](std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  ASSERT_EQ(run(with(base, {"--samples", "0", "8", "--aov", "depth", "-o", (in / "a.exr").string()})), 0);
  ASSERT_EQ(run(with(base, {"--samples", "8", "16", "--aov", "depth", "-o", (in / "b.exr").string()})), 0);
  const std::vector<std::string> partials = {(in / "a.exr").string(), (in / "b.exr").string()};

  const std::vector<Writer> writers = {
      {"slice",
       with(base, {"--samples", "0", "32", "--aov", "depth", "-o", (out / "part.exr").string()}),
       {"part.exr"}},
      {"merge",
       with({kMerge, (out / "merged.png").string()},
            with(partials, {"--aov", "depth=" + (out / "merged_depth.exr").string(), "-q"})),
       {"merged.png", "merged_depth.exr"}},
      {"merge to a partial",
       with({kMerge, (out / "m.partial.exr").string()}, with(partials, {"-q"})),
       {"m.partial.exr"}},
      {"decide-lines", with(base, {"--decide-lines", (out / "lines.bin").string()}), {"lines.bin"}},
      {"checkpoint",
       with(base, {"--spp", "12", "--checkpoint", "0.000001", "-o", (out / "still.png").string()}),
       {"still.png"}},
  };
  constexpr int kKillsEach = 8;
  for (const Writer& w : writers) {
    SCOPED_TRACE(w.name);
    const double run_ms = milliseconds_of(w.args);
    size_t left_behind = 0;
    for (int k = 0; k < kKillsEach; ++k) {
      SCOPED_TRACE("kill " + std::to_string(k));
      const bool in_rename = k % 2 == 0;
      const pid_t pid = start(w.args, in_rename ? 20 : 0);
      if (in_rename) {
        if (wait_for_entry(pid, out, ".inkray-tmp-")) sleep_ms(1.0 + 4.0 * (k / 2));
      } else {
        sleep_ms(run_ms * (0.15 + 0.25 * (k / 2)));
      }
      kill_and_reap(pid);
      left_behind += debris(dir.path()).size();
      ASSERT_EQ(run(w.args), 0);
      EXPECT_EQ(debris(dir.path()), Names{});
      EXPECT_EQ(entries(out), w.files);
    }
    EXPECT_GT(left_behind, 0u) << "no kill left anything to clean up";
    std::printf("[          ] %s: %d kills left %zu temporaries, all gone after the next run\n",
                w.name.c_str(), kKillsEach, left_behind);
    for (const std::string& f : w.files) fs::remove(out / f);
  }
}

}  // namespace
}  // namespace inkray
