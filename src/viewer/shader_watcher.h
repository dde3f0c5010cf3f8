#pragma once
// Hot reload: notices when any *.glsl file below a directory is modified, added or removed, by polling
// modification times and sizes (portable, and cheap at two polls a second for a few dozen files).
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace fp {

class ShaderWatcher {
  public:
    // Takes the first snapshot now; later changes are measured against it.
    explicit ShaderWatcher(std::string directory, double intervalSeconds = 0.5);

    // True when the files differ from the last snapshot. Looks at the disk at most once per interval
    // (`now` in seconds, any monotonic origin); in between it returns false.
    bool poll(double now);
    const std::string& directory() const { return directory_; }

  private:
    struct Stamp {
        std::filesystem::file_time_type modified;
        std::uintmax_t size = 0;
        bool operator==(const Stamp& o) const { return modified == o.modified && size == o.size; }
    };
    using Snapshot = std::map<std::string, Stamp>;
    Snapshot snapshot() const;

    std::string directory_;
    double interval_;
    double lastPoll_;
    Snapshot files_;
};

}  // namespace fp
