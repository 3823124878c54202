// What a ray meets: every node in turn, or the spheres through the BVH in the HEXRAY_BVH variant.

Hit findNearestHit(Ray ray) {
#ifdef HEXRAY_BVH
    return findNearestHitInBvh(ray);
#else
    Hit hit = Hit(NO_HIT, NO_NODE);
    for (uint i = 0u; i < nodeCount(); ++i) {
        real t = cameraRayDistance(ray, i);
        // On an exact tie the earlier node keeps the hit (strict <), as the course specifies.
        if (t < hit.t) {
            hit = Hit(t, i);
        }
    }
    return hit;
#endif
}

// Whether anything lies strictly between the ray's origin and `target`, `distance` away.
bool isOccluded(Ray ray, vec3r target, real distance) {
#ifdef HEXRAY_BVH
    return isOccludedInBvh(ray, target, distance);
#else
    // Unrolled (node count specialised), the loop stays straight-line code; a data-driven one
    // stops at the first blocker.
    bool blocked = false;
    for (uint i = 0u; i < nodeCount() && (NODES_SPECIALISED || !blocked); ++i) {
        blocked = blocksSegment(ray, i, target, distance) || blocked;
    }
    return blocked;
#endif
}
