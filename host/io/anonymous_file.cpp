#include "io/anonymous_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>

#include "io/removed_on_signal.h"
#include "io/temporary_names.h"

namespace hexray::inline io {
namespace {

// A named temporary (registered for removal on signals until then), removed at once.
int openUnlinkedTemporary(const std::string& directory) {
    const std::string pattern = directory + "/" + std::string(kPartialFilePrefix) + "scratch.XXXXXX";
    RegisteredTemporary temporary = createTemporary(pattern, RemovedOnSignal::Kind::File);
    if (temporary.descriptor >= 0) {
        ::unlink(temporary.path.c_str());
    }
    return temporary.descriptor;
}

}  // namespace

std::string scratchDirectory() {
    const char* directory = std::getenv("TMPDIR");
    return directory && *directory ? directory : "/tmp";
}

FilePointer openAnonymousFile() {
    const std::string directory = scratchDirectory();
    int descriptor = ::open(directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    if (descriptor < 0 && (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL)) {
        descriptor = openUnlinkedTemporary(directory);
    }
    if (descriptor < 0) {
        return nullptr;
    }
    FilePointer file(::fdopen(descriptor, "w+b"));
    if (!file) {
        const int error = errno;
        ::close(descriptor);
        errno = error;
    }
    return file;
}

}  // namespace hexray::io
