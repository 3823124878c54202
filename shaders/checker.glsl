// The checker shader's cell parity on a plane ((u, v) = (x, z)) and on a sphere ((u, v) =
// longitude and latitude of the outward normal, in degrees).
#ifndef HEXRAY_CHECKER_GLSL
#define HEXRAY_CHECKER_GLSL

#include "precision.glsl"

// 0 or 1 for a number holding an integer; exact at any magnitude (x/2 and floor are exact).
real parity(real wholeNumber) {
    return mod(wholeNumber, 2.0);
}

bool isOddCell(vec2r cell, real eyeParity) {
    return parity(parity(cell.x) + parity(cell.y) + eyeParity) != 0.0;
}

// `checker`: .x square size, .yz the eye's fractional cell position (from the host, in double),
// .w the parity of the eye's whole cells; `position` camera-relative.
// The position's place among the plane's cells, in cells from the eye's cell's corner: its floor is
// the cell. A product with the reciprocal, which the driver folds to a constant for a generated kernel.
vec2r planeCell(vec4r checker, vec3r position) {
    return checker.yz + position.xz * (1.0 / checker.x);
}

bool isOddPlaneCell(vec4r checker, vec3r position) {
    return isOddCell(floor(planeCell(checker, position)), checker.w);
}

// GLSL has atan in float only, so the f64 variant computes the angles in float too. Latitude is
// asin(n.y), computed as atan(n.y, |n.xz|): drivers may approximate asin coarsely (Mesa's is
// off by ~1e-4 rad, enough to move checker edges by a visible fraction of a pixel), atan closely.
bool isOddSphereCell(vec4r checker, vec3r outwardNormal) {
    vec3 n = vec3(outwardNormal);
    vec2 uv = degrees(vec2(atan(n.x, n.z), atan(n.y, length(n.xz))));
    return isOddCell(floor(vec2r(uv) / checker.x), checker.w);
}

#endif  // HEXRAY_CHECKER_GLSL
