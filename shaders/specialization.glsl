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

bool isPlane(uint node) {
    return NODES_SPECIALISED ? ((SPHERE_NODES >> node) & 1u) == 0u : nodes[node].kinds.x == GEOMETRY_PLANE;
}

bool isConstantShaded(uint node) {
    return NODES_SPECIALISED ? ((CONSTANT_NODES >> node) & 1u) != 0u : nodes[node].kinds.y == SHADER_CONSTANT;
}

bool isCheckerShaded(uint node) {
    return NODES_SPECIALISED ? ((CHECKER_NODES >> node) & 1u) != 0u : nodes[node].kinds.y == SHADER_CHECKER;
}
