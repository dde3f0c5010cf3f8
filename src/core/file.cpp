#include "core/file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.h"

namespace fp {

namespace fs = std::filesystem;

std::string readFileBytes(const std::string& path) {
    if (path.empty()) throw Error("no input file given (empty path)");
    std::error_code ec;
    fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) throw Error(path + ": no such file");
    if (fs::is_directory(status)) throw Error(path + ": is a directory, not a file");
    if (!fs::is_regular_file(status)) throw Error(path + ": is not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open: " + std::strerror(errno));
    // One read into a string of the file's size, not a character at a time: a million-triangle OBJ is
    // tens of megabytes. Then whatever follows, the slow way, for a file that grew meanwhile or whose
    // size the system does not know (/proc).
    const uintmax_t size = fs::file_size(path, ec);
    std::string bytes(ec ? 0 : size_t(size), '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    bytes.resize(size_t(in.gcount()));  // a file that shrank meanwhile
    if (in.bad()) throw Error(path + ": read error");
    in.clear();
    bytes.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error(path + ": read error");
    return bytes;
}

void checkWritablePath(const std::string& path, const std::string& label) {
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    const std::string what = label + " " + path;
    if (!fs::is_directory(dir)) throw Error(what + ": directory " + dir.string() + " does not exist");
    if (access(dir.c_str(), W_OK) != 0)
        throw Error(what + ": directory " + dir.string() + " is not writable");
    if (fs::is_directory(path)) throw Error(what + " is a directory");
}

}  // namespace fp
