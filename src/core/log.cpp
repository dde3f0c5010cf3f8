#include "core/log.h"

#include <cstdio>

#include "core/error.h"

namespace fp {

static WarningCapture* activeCapture = nullptr;
static bool strict = false;

void setStrictWarnings(bool on) {
    strict = on;
}

bool strictWarnings() {
    return strict;
}

void warn(const std::string& message) {
    if (strict) throw Error(message + " (an error with --strict)");
    if (activeCapture) {
        activeCapture->messages_.push_back(message);
        return;
    }
    std::fprintf(stderr, "warning: %s\n", message.c_str());
}

void note(const std::string& message) {
    if (activeCapture) {
        activeCapture->notes_.push_back(message);
        return;
    }
    std::fprintf(stderr, "note: %s\n", message.c_str());
}

WarningCapture::WarningCapture() : previous_(activeCapture) {
    activeCapture = this;
}
WarningCapture::~WarningCapture() {
    activeCapture = previous_;
}

bool WarningCapture::contains(const std::string& fragment) const {
    for (const std::string& m : messages_)
        if (m.find(fragment) != std::string::npos) return true;
    return false;
}

}  // namespace fp
