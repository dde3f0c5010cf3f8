#pragma once
// Warnings about input that was repaired rather than rejected (dropped triangles, default materials...).
// They go to stderr; tests install a WarningCapture to assert on them.
#include <string>
#include <vector>

namespace fp {

void warn(const std::string& message);

// While alive, warnings are collected here instead of printed (not thread-safe; one at a time).
class WarningCapture {
  public:
    WarningCapture();
    ~WarningCapture();
    WarningCapture(const WarningCapture&) = delete;
    WarningCapture& operator=(const WarningCapture&) = delete;
    const std::vector<std::string>& messages() const { return messages_; }
    bool contains(const std::string& fragment) const;

  private:
    friend void warn(const std::string& message);
    std::vector<std::string> messages_;
    WarningCapture* previous_;
};

}  // namespace fp
