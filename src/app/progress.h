#pragma once
// A one-line progress bar with ETA on stderr, drawn only when stderr is a terminal.
#include <chrono>

namespace fp {

class Progress {
  public:
    explicit Progress(int total);
    void update(int done);
    void finish();  // clears the line

  private:
    int total_;
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace fp
