// What the host knows about the scene when it builds the pipeline, as specialization
// constants: the driver's compiler then unrolls the loops over nodes and lights and removes
// every geometry and shader path the scene does not use. Scenes with more than 32 nodes or
// lights keep the data-driven loops (DYNAMIC).

const uint DYNAMIC = 0xffffffffu;
layout(constant_id = 2) const uint SCENE_NODE_COUNT = DYNAMIC;
layout(constant_id = 3) const uint SCENE_LIGHT_COUNT = DYNAMIC;
layout(constant_id = 4) const uint SPHERE_NODES = 0u;    // bit i: node i is a sphere (else a plane)
layout(constant_id = 5) const uint CONSTANT_NODES = 0u;  // bit i: node i is constant-shaded
layout(constant_id = 6) const uint CHECKER_NODES = 0u;   // bit i: node i is checker-shaded
// What the render produces (GpuOutput on the host): linear RGB and the classification, for
// comparisons; or only the finished 8-bit image, encoded here so the host has nothing to do.
const uint OUTPUT_LINEAR_AND_CLASSES = 0u;
const uint OUTPUT_8BIT_LINEAR = 1u;
const uint OUTPUT_8BIT_SRGB = 2u;
layout(constant_id = 7) const uint OUTPUT_MODE = OUTPUT_LINEAR_AND_CLASSES;
layout(constant_id = 8) const uint SAMPLES_PER_PIXEL = 1u;  // anti-aliasing

const bool NODES_SPECIALISED = SCENE_NODE_COUNT != DYNAMIC;

uint nodeCount() {
    return NODES_SPECIALISED ? SCENE_NODE_COUNT : frame.nodeCount;
}

uint lightCount() {
    return SCENE_LIGHT_COUNT != DYNAMIC ? SCENE_LIGHT_COUNT : frame.lightCount;
}

// The node kinds the scene has at all. lavapipe runs both sides of every branch whichever
// way its lanes go, so a path the scene cannot take still costs its full price unless these
// fold it away at compile time.
const uint SCENE_NODES = SCENE_NODE_COUNT >= 32u ? 0xffffffffu : (1u << SCENE_NODE_COUNT) - 1u;
const uint PLANE_NODES = SCENE_NODES & ~SPHERE_NODES;
const uint LIT_NODES = SCENE_NODES & ~CONSTANT_NODES;

// Whether `node`, one of the nodes in `candidates` (a bit set), is also in `subset`; known
// at compile time when the candidates all lie inside or all outside the subset.
bool nodeIn(uint node, uint subset, uint candidates) {
    if ((candidates & subset) == 0u) {
        return false;
    }
    if ((candidates & ~subset) == 0u) {
        return true;
    }
    return ((subset >> node) & 1u) != 0u;
}

bool isPlane(uint node) {
    return NODES_SPECIALISED ? nodeIn(node, PLANE_NODES, SCENE_NODES) : nodes[node].kinds.x == GEOMETRY_PLANE;
}

// The same question about a node known to be lit (not constant-shaded) or checker-shaded:
// a scene whose checkers are all planes, say, then has no checker-sphere code at all.
bool isLitPlane(uint node) {
    return NODES_SPECIALISED ? nodeIn(node, PLANE_NODES, LIT_NODES) : isPlane(node);
}

bool isCheckerPlane(uint node) {
    return NODES_SPECIALISED ? nodeIn(node, PLANE_NODES, CHECKER_NODES) : isPlane(node);
}

bool isConstantShaded(uint node) {
    return NODES_SPECIALISED ? nodeIn(node, CONSTANT_NODES, SCENE_NODES) : nodes[node].kinds.y == SHADER_CONSTANT;
}

bool isCheckerShaded(uint node) {
    return NODES_SPECIALISED ? nodeIn(node, CHECKER_NODES, LIT_NODES) : nodes[node].kinds.y == SHADER_CHECKER;
}
