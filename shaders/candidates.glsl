// Candidate lists, in render.comp's HEXRAY_CANDIDATES variant: for each cell of a grid over the
// directions seen from the eye, and from each light, the spheres a ray in that direction can meet
// (built on the host, conservatively: host/accel/candidate_lists.h). A ray looks its cell up by its
// own direction and tests that cell's spheres only; planes, unbounded, are listed in one cell of
// their own. Every buffer here is a uniform texel buffer (see shader_interface.h).
#ifndef HEXRAY_CANDIDATES_GLSL
#define HEXRAY_CANDIDATES_GLSL

#include "precision.glsl"
#include "scene_data.glsl"
#include "shader_interface.h"
#include "texels.glsl"

// Texels 0 to 2: the camera's right, down and forward axes (floats). Then three texels per grid
// (host/layout/gpu_layout.h's GpuCandidateGrid), over tangent coordinates (u, v) =
// (d . right, d . down) / (d . forward) of a direction d from the grid's origin.
layout(set = 0, binding = CANDIDATE_GRID_BINDING) uniform usamplerBuffer candidateGrids;
// Cell c lists entries cellStarts[c] to cellStarts[c + 1].
layout(set = 0, binding = CANDIDATE_CELL_BINDING) uniform usamplerBuffer cellStarts;
layout(set = 0, binding = CANDIDATE_ENTRY_BINDING) uniform usamplerBuffer candidateEntries;
// One record per sphere, in the lists' order (CandidateLists::sphereNodes), in two arrays (see
// gpu_layout.h's GpuCandidateSphereNode): every record's centre and radius, then every record's eye
// power, node index and look.
layout(set = 0, binding = CANDIDATE_SPHERE_BINDING) uniform usamplerBuffer candidateSpheres;

struct CandidateRange {
    uint first;
    uint end;
    bool depthOrdered;  // nearest first from the view's origin (liesBeyond)
};

uint cellStart(uint cell) {
    return texelFetch(cellStarts, int(cell)).x;
}

uint candidateEntry(uint k) {
    return texelFetch(candidateEntries, int(k)).x;
}

// A record's centre and radius: all a shadow ray reads.
vec4r candidateSphereGeometry(uint index) {
    return realVec4At(candidateSpheres, REAL_VEC4_TEXELS * int(index));
}

// The rest of a record: what a camera ray reads of a sphere it may hit.
struct CandidateSphereNode {
    real eyePower;
    uint node;
    uint look;
};

CandidateSphereNode candidateSphereNode(uint index) {
    uint records = frame.nodeCount - frame.planeCount;  // every sphere has one
    uvec4 texel = texelFetch(candidateSpheres, REAL_VEC4_TEXELS * int(records) + int(index));
#ifdef HEXRAY_F64
    return CandidateSphereNode(packDouble2x32(texel.xy), texel.z, texel.w);
#else
    return CandidateSphereNode(uintBitsToFloat(texel.x), texel.y, texel.z);
#endif
}

// Whether a sphere of radius `radius` whose centre lies `distanceSquared` (|f|^2) from a view's
// origin lies past `rayLength` along every ray from it, its test's rounding included: whether its
// depth (shader_interface.h's DEPTH_ORDER_UNITS) passes the ray's end by DEPTH_ORDER_SLACK of it.
// In a depth-ordered list every later sphere then does too. Squares of sums of positive terms: no
// cancellation, so the slack covers this test's own rounding.
bool liesBeyond(real distanceSquared, real radius, real rayLength) {
    real margin = real(DEPTH_ORDER_UNITS) * UNIT_ROUNDOFF;
    real end = rayLength + radius * (1.0 + margin);
    real shrink = (1.0 - margin) * (1.0 - margin) * (1.0 - real(DEPTH_ORDER_SLACK));
    return distanceSquared * shrink > end * end * (1.0 + real(DEPTH_ORDER_SLACK));
}

// Cell PLANE_CELL: the first of the lists, which the frame counts (a load for the whole SIMD group).
CandidateRange planeCandidates() {
    return CandidateRange(0u, frame.planeCount, false);
}

// Where cell (column, row) of a grid of `size` (columns, rows) cells lies among its cells: in
// bands of rows (shader_interface.h's CELL_BAND_ROWS), column after column within a band.
uint cellIndex(uvec2 size, uvec2 cell) {
    uint bandStart = cell.y - cell.y % CELL_BAND_ROWS;
    uint bandRows = min(CELL_BAND_ROWS, size.y - bandStart);
    return bandStart * size.x + cell.x * bandRows + cell.y % CELL_BAND_ROWS;
}

// The list of the cell of grid `grid` that holds `tangent`; empty outside the grid, where no
// sphere's directions reach (a NaN tangent, from a zero direction, is outside). A ray longer than
// the grid's reach takes the list the grid names for it instead.
CandidateRange gridCandidates(uint grid, vec2 tangent, float rayLength) {
    int base = 3 + 3 * int(grid);
    vec4 window = uintBitsToFloat(texelFetch(candidateGrids, base));
    uvec4 cells = texelFetch(candidateGrids, base + 1);
    vec2 reachAndOrder = uintBitsToFloat(texelFetch(candidateGrids, base + 2).xy);
    vec2 position = (tangent - window.xy) * window.zw;
    bool inside = all(greaterThanEqual(position, vec2(0.0))) && all(lessThan(position, vec2(cells.xy)));
    uvec2 cell = uvec2(clamp(position, vec2(0.0), vec2(cells.xy - 1u)));
    bool pastReach = rayLength > reachAndOrder.x;
    uint index = pastReach ? cells.w : cells.z + cellIndex(cells.xy, cell);
    uint first = cellStart(index);
    return CandidateRange(first, inside || pastReach ? cellStart(index + 1u) : first, reachAndOrder.y > 0.0 && !pastReach);
}

// The spheres a camera ray with this direction can meet.
CandidateRange cameraCandidates(vec3 direction) {
    vec3 right = uintBitsToFloat(texelFetch(candidateGrids, 0).xyz);
    vec3 down = uintBitsToFloat(texelFetch(candidateGrids, 1).xyz);
    vec3 forward = uintBitsToFloat(texelFetch(candidateGrids, 2).xyz);
    vec2 across = vec2(dot(direction, right), dot(direction, down));
    return gridCandidates(CAMERA_GRID, across / dot(direction, forward), 0.0);
}

// The spheres a segment from light `light` along `fromLight`, `rayLength` long, can meet. The cube
// face is the direction's largest component; its tangent axes are the next two, in cyclic order.
CandidateRange lightCandidates(uint light, vec3 fromLight, float rayLength) {
    vec3 size = abs(fromLight);
    bool x = size.x >= size.y && size.x >= size.z;
    bool y = !x && size.y >= size.z;
    float major = x ? fromLight.x : (y ? fromLight.y : fromLight.z);
    vec2 across = x ? fromLight.yz : (y ? fromLight.zx : fromLight.xy);
    uint face = (x ? 0u : (y ? 2u : 4u)) + (major < 0.0 ? 1u : 0u);
    return gridCandidates(CAMERA_GRID + 1u + CUBE_FACES * light + face, across / abs(major), rayLength);
}

#endif  // HEXRAY_CANDIDATES_GLSL
