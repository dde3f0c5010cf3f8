#pragma once
// Repairs are reported once per kind, with a count and the first line, not once per triangle: a broken
// exporter can produce a million bad triangles, and one warning saying so is more useful than a million.
#include <cstddef>
#include <string>

namespace fp {

class RepairTally {
  public:
    void add(int line, size_t n = 1) {
        if (n == 0) return;
        if (count_ == 0) firstLine_ = line;
        count_ += n;
    }
    size_t count() const { return count_; }
    int firstLine() const { return firstLine_; }

    // "<verb> <count> <noun>[s] <rest>", e.g. "dropped 3 degenerate triangles"; pluralizes `noun` only.
    std::string describe(const std::string& verb, const std::string& noun,
                         const std::string& rest = "") const;
    // Warns "<file>: <describe(...)> (first at line L)" if anything was counted.
    void report(const std::string& file, const std::string& verb, const std::string& noun,
                const std::string& rest = "") const;

  private:
    size_t count_ = 0;
    int firstLine_ = 0;
};

}  // namespace fp
