// Preloaded into the sanitizer build's tests (ci/sanitize.sh): dlclose does nothing, so the
// Vulkan loader's drivers and layers stay mapped until exit. LeakSanitizer symbolizes leak
// stacks at exit; in a library already unloaded they show as "<unknown module>", which no
// suppression in ci/lsan.supp can match.
int dlclose(void* handle) {
    (void)handle;
    return 0;
}
