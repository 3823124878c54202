// The rules every kernel applies the same way, the data-driven one (render.comp) and those
// generated for one scene (host/kernels/kernel_generator.cpp): written once, so that the two
// cannot drift apart. A generated kernel passes constants, and the compiler folds what they decide.
#ifndef HEXRAY_KERNEL_POLICIES_GLSL
#define HEXRAY_KERNEL_POLICIES_GLSL

#include "precision.glsl"
#include "ray.glsl"
#include "surface.glsl"

// On an exact tie the lower node index keeps the hit, as the course specifies ("the earlier
// node"), in whichever order the nodes are tested; two misses are no tie.
Hit nearer(Hit hit, real t, uint node) {
    return t < hit.t || (t == hit.t && t != NO_HIT && node < hit.node) ? Hit(t, node) : hit;
}

// Whether a node found between the surface of the hit and a light (`blocks`) shadows it;
// `isHitsSphere`: it is the hit's own sphere. A sphere the camera sees from outside cannot shadow
// its own visible points (convexity), so its own test is left out; that is also why its shadow rays
// may start right on it.
bool castsShadow(bool blocks, bool isHitsSphere, bool seenFromOutside) {
    return blocks && !(seenFromOutside && isHitsSphere);
}

bool castsShadow(bool blocks, uint node, Hit hit, bool seenFromOutside) {
    return castsShadow(blocks, node == hit.node, seenFromOutside);
}

// Where the shadow rays of surface `s` on `sphere` start: on the surface when the camera sees the
// sphere from outside (see castsShadow), pushed off it when the camera is inside, where the sphere
// is among its own shadow tests.
vec3r sphereShadowOrigin(Surface s, vec4r sphere, bool eyeInside) {
    return eyeInside ? shadowOriginOffSphere(s, sphere) : s.shadowOrigin;
}

#endif  // HEXRAY_KERNEL_POLICIES_GLSL
