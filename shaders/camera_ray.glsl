// Primary rays through the course's pixel sheet (set up on the host, see host/camera/camera.h).

Ray primaryRay(uvec2 pixel) {
    vec2 s = (vec2(pixel) + frame.samplingOffset) / vec2(frame.imageSize);
    vec3 target = frame.sheetTopLeft.xyz + frame.sheetRight.xyz * s.x + frame.sheetDown.xyz * s.y;
    // The eye is the origin; camera rays start there exactly and accept any t > 0.
    return Ray(vec3(0.0), normalize(target));
}
