// Rays and the hits along them.

struct Ray {
    vec3 origin;
    vec3 direction;  // unit length
};

// Farther than any hit: float32's largest finite value (GLSL has no constant infinity).
const float NO_HIT = 3.4028235e38;
const uint NO_NODE = 0xffffffffu;

struct Hit {
    float t;
    uint node;
};
