// `hexray merge OUT PIECES...`: the pieces of a tiled render (`render --tile I/N`) assembled into
// the whole image.

#include <cstdio>

#include "cli/command_support.h"
#include "io/output_plan.h"
#include "io/standard_output.h"
#include "tile/tile_merge.h"

namespace hexray::cli {

int runMerge(const MergeOptions& options) {
    return guarded([&] {
        OutputPlan plan;
        for (const std::string& piece : options.piecePaths) {
            plan.addInput("the piece", piece);
        }
        plan.addFile("the output", options.outputPath);
        plan.check();
        const TileStamp stamp = mergeTiles(options.outputPath, options.piecePaths);
        std::printf("wrote %s (%ux%u) from %u pieces\n", displayName(options.outputPath).c_str(), stamp.width,
                    stamp.height, stamp.tile.count);
        return int(kSuccess);
    });
}

}  // namespace hexray::cli
