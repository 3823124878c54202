// Rays and the hits along them.

struct Ray {
    vec3r origin;
    vec3r direction;  // unit length
};

const real NO_HIT = REAL_MAX;
const uint NO_NODE = BACKGROUND;

struct Hit {
    real t;
    uint node;
};
