// `hexray merge OUT PIECES...`: the pieces of a render in strips (`render --strip I/N`) assembled into
// the whole image.

#include <cstdio>

#include "cli/command_support.h"
#include "cli/quiet.h"
#include "io/output_plan.h"
#include "io/standard_output.h"
#include "strip/strip_merge.h"

namespace hexray::cli {

int runMerge(const MergeOptions& options) {
    return guarded([&] {
        OutputPlan plan;
        for (const std::string& piece : options.piecePaths) {
            plan.addInput("the piece", piece);
        }
        plan.addFile("the output", options.outputPath);
        plan.check();
        const StripStamp stamp = mergeStrips(options.outputPath, options.piecePaths);
        if (!quiet()) {
            std::printf("wrote %s (%ux%u) from %u pieces\n", displayName(options.outputPath).c_str(), stamp.width,
                        stamp.height, stamp.strip.count);
        }
        return int(kSuccess);
    });
}

}  // namespace hexray::cli
