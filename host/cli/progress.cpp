#include "cli/progress.h"

#include <unistd.h>

#include <cstdio>

#include "cli/quiet.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

constexpr auto kRedrawInterval = std::chrono::milliseconds(100);

std::string amount(std::uint64_t done, std::uint64_t total, Progress::Unit unit) {
    char text[96];
    if (unit != Progress::Unit::Bytes) {
        std::snprintf(text, sizeof text, "%llu of %llu %s", static_cast<unsigned long long>(done),
                      static_cast<unsigned long long>(total), unit == Progress::Unit::Rows ? "rows" : "measurements");
    } else {
        std::snprintf(text, sizeof text, "%.1f of %.1f MB", double(done) * 1e-6, double(total) * 1e-6);
    }
    return text;
}

std::string timeLeft(double seconds) {
    char text[48];
    if (seconds < 60) {
        std::snprintf(text, sizeof text, "%.1f s left", seconds);
    } else {
        const long whole = long(seconds);
        std::snprintf(text, sizeof text, "%ld min %02ld s left", whole / 60, whole % 60);
    }
    return text;
}

}  // namespace

Progress::Progress(std::string task, std::uint64_t total, Unit unit)
    : task_(printable(task)), total_(total), unit_(unit), shown_(shown()), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
    if (drawn_) {
        std::fprintf(stderr, "\r\033[K");  // erase the line
        std::fflush(stderr);
    }
}

void Progress::update(std::uint64_t done) {
    const auto now = std::chrono::steady_clock::now();
    if (!shown_ || done == 0 || done >= total_ || (drawn_ && now - lastDrawn_ < kRedrawInterval)) {
        return;
    }
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double left = elapsed * double(total_ - done) / double(done);
    std::fprintf(stderr, "\r\033[K%s: %u%% (%s), %s", task_.c_str(), unsigned(100 * done / total_),
                 amount(done, total_, unit_).c_str(), timeLeft(left).c_str());
    std::fflush(stderr);
    drawn_ = true;
    lastDrawn_ = now;
}

bool Progress::shown() {
    return !quiet() && ::isatty(STDERR_FILENO) != 0;
}

}  // namespace hexray::cli
