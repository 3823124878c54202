#pragma once
// How far a long task has got, on one line of standard error redrawn in place:
//   rendering scenes/big.json: 42% (6912 of 16384 rows), 3.1 s left
// and erased when the task ends. Only when standard error is a terminal: a log file or a pipe
// gets nothing, and neither does --quiet.

#include <chrono>
#include <cstdint>
#include <string>

namespace hexray::cli {

class Progress {
public:
    enum class Unit { Rows, Bytes, Measurements };

    // `task` begins the line ("rendering scene.json"); `total` units make the whole.
    Progress(std::string task, std::uint64_t total, Unit unit = Unit::Rows);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // `done` of the total are done. Redraws at most ten times a second; the first time at once.
    void update(std::uint64_t done);

    // Whether progress lines are shown: standard error is a terminal and --quiet was not given.
    static bool shown();

private:
    std::string task_;
    std::uint64_t total_;
    Unit unit_;
    bool shown_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastDrawn_;
};

}  // namespace hexray::cli
