#include "viewer/shader_watcher.h"

#include <system_error>

namespace fp {

ShaderWatcher::ShaderWatcher(std::string directory, double intervalSeconds)
    : directory_(std::move(directory)), interval_(intervalSeconds), lastPoll_(-1e300), files_(snapshot()) {}

ShaderWatcher::Snapshot ShaderWatcher::snapshot() const {
    namespace fs = std::filesystem;
    Snapshot files;
    // error_code overloads throughout: an editor replacing a file mid-scan must not stop the viewer.
    std::error_code error;
    for (fs::recursive_directory_iterator it(directory_, error), end; !error && it != end;
         it.increment(error)) {
        if (it->path().extension() != ".glsl") continue;
        std::error_code fileError;
        Stamp stamp;
        stamp.modified = fs::last_write_time(it->path(), fileError);
        stamp.size = fs::file_size(it->path(), fileError);
        if (!fileError) files[it->path().string()] = stamp;
    }
    return files;
}

bool ShaderWatcher::poll(double now) {
    if (now - lastPoll_ < interval_) return false;
    lastPoll_ = now;
    Snapshot current = snapshot();
    if (current == files_) return false;
    files_ = std::move(current);
    return true;
}

}  // namespace fp
