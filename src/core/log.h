#pragma once
// Warnings about input that was repaired rather than rejected (dropped triangles, default materials, a
// missing texture, a scene without light...). They go to stderr; tests install a WarningCapture to
// assert on them. In strict mode (--strict, for batch pipelines that would rather stop than render a
// repaired scene) every warning is an error instead: warn() throws fp::Error with the same message.
#include <string>
#include <vector>

namespace fp {

// Prints "warning: <message>" to stderr (or hands it to the active WarningCapture); in strict mode
// throws fp::Error(message + " (an error with --strict)") instead, whether or not a capture is active.
void warn(const std::string& message);

// Prints "note: <message>" to stderr (or hands it to the active WarningCapture's notes): a default the
// program chose that the user may want to know about (the studio light a model without light gets). Not
// a repair, so never an error, in strict mode either.
void note(const std::string& message);

// Strict mode is process-wide and off until set (the render request sets it from --strict).
void setStrictWarnings(bool strict);
bool strictWarnings();

// While alive, warnings (and notes, apart) are collected here instead of printed (not thread-safe; one at a
// time).
class WarningCapture {
  public:
    WarningCapture();
    ~WarningCapture();
    WarningCapture(const WarningCapture&) = delete;
    WarningCapture& operator=(const WarningCapture&) = delete;
    const std::vector<std::string>& messages() const { return messages_; }
    const std::vector<std::string>& notes() const { return notes_; }
    bool contains(const std::string& fragment) const;

  private:
    friend void warn(const std::string& message);
    friend void note(const std::string& message);
    std::vector<std::string> messages_, notes_;
    WarningCapture* previous_;
};

}  // namespace fp
