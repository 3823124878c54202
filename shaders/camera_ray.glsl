// Primary rays through the course's pixel sheet (set up on the host, see host/camera/camera.h).

Ray primaryRay(uvec2 pixel) {
    vec2r s = (vec2r(pixel) + real(frame.samplingOffset)) / vec2r(frame.imageSize);
    vec3r target = frame.sheetTopLeft.xyz + frame.sheetRight.xyz * s.x + frame.sheetDown.xyz * s.y;
    // Camera rays start at the eye exactly and accept any t > 0.
    return Ray(frame.origin.xyz, normalize(target));
}
