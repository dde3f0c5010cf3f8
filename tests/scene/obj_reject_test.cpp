// OBJ input that must be refused with an fp::Error naming the file (and the line, for content errors).
#include <gtest/gtest.h>

#include "scene/load.h"
#include "scene_test_util.h"

namespace fp {
namespace {

using test::errorOf;

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

// Loads `text` as an OBJ file and returns the error; expects it to name the file and, if line > 0,
// carry "<file>:<line>:".
std::string rejectObj(const std::string& text, int line = 0) {
    test::TempDir dir;
    std::string path = dir.write("bad.obj", text);
    std::string message = errorOf([&] { loadObj(path); });
    EXPECT_CONTAINS_ALL(message, path);
    if (line > 0) EXPECT_CONTAINS_ALL(message, path + ":" + std::to_string(line) + ":");
    return message;
}

TEST(ObjReject, MissingFile) {
    test::TempDir dir;
    std::string path = dir.path("nothing.obj");
    EXPECT_CONTAINS_ALL(errorOf([&] { loadObj(path); }), path, "no such file");
    EXPECT_CONTAINS_ALL(errorOf([&] { loadScene(path); }), path, "no such file");
}

TEST(ObjReject, EmptyPath) {
    EXPECT_CONTAINS_ALL(errorOf([] { loadObj(""); }), "empty path");
    EXPECT_CONTAINS_ALL(errorOf([] { loadScene(""); }), "empty path");
}

TEST(ObjReject, Directory) {
    // tinyobjloader "loads" a directory as an empty mesh.
    test::TempDir dir;
    std::string path = dir.path("folder.obj");
    std::filesystem::create_directories(path);
    EXPECT_CONTAINS_ALL(errorOf([&] { loadObj(path); }), path, "is a directory");
    EXPECT_CONTAINS_ALL(errorOf([&] { loadScene(path); }), path, "is a directory");
}

TEST(ObjReject, EmptyFile) {
    EXPECT_CONTAINS_ALL(rejectObj(""), "empty");
    EXPECT_CONTAINS_ALL(rejectObj(" \n\t\r\n"), "empty");
    EXPECT_CONTAINS_ALL(rejectObj("\xEF\xBB\xBF"), "empty");
}

TEST(ObjReject, NoFaces) {
    EXPECT_CONTAINS_ALL(rejectObj("# just a comment\no thing\n"), "no faces");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle), "no faces");
}

TEST(ObjReject, BinaryWithNulBytes) {
    std::string junk = kTriangle + std::string("f 1 2 3\n\0\0\x01\x02\xff\xfe junk", 16);
    EXPECT_CONTAINS_ALL(rejectObj(junk), "binary", "NUL", "line 5");
    EXPECT_CONTAINS_ALL(rejectObj(std::string("\x7f"
                                              "ELF\x02\x01\x01\0\0\0",
                                              10)),
                        "binary", "byte 0x02");
}

TEST(ObjReject, PngImage) {
    std::string png("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
    EXPECT_CONTAINS_ALL(rejectObj(png), "PNG image");
}

TEST(ObjReject, Utf16Text) {
    // "v 0 0 0" as UTF-16 with either byte-order mark.
    std::string le(
        "\xFF\xFEv\0 \0"
        "0\0 \0"
        "0\0 \0"
        "0\0\n\0",
        18);
    std::string be(
        "\xFE\xFF\0v\0 \0"
        "0\0 \0"
        "0\0 \0"
        "0\0\n",
        18);
    EXPECT_CONTAINS_ALL(rejectObj(le), "UTF-16");
    EXPECT_CONTAINS_ALL(rejectObj(be), "UTF-16");
    EXPECT_CONTAINS_ALL(rejectObj(std::string("\xFF\xFE\0\0v\0\0\0", 8)), "UTF-32");
}

TEST(ObjReject, MalformedNumbers) {
    // tinyobjloader reads all of these as 0 without a word.
    EXPECT_CONTAINS_ALL(rejectObj("v 0 0 0\nv 1 0 0\nv 1.0 abc 2\nf 1 2 3\n", 3), "malformed number",
                        "'abc'");
    EXPECT_CONTAINS_ALL(rejectObj("v 0 0 0\nv 1,5 0 0\n", 2), "'1,5'");
    EXPECT_CONTAINS_ALL(rejectObj("v 0x10 0 0\n", 1), "'0x10'");
    EXPECT_CONTAINS_ALL(rejectObj("v 1e 0 0\n", 1), "'1e'");
    EXPECT_CONTAINS_ALL(rejectObj("v 1.2.3 0 0\n", 1), "'1.2.3'");
    EXPECT_CONTAINS_ALL(rejectObj("v . 0 0\n", 1), "'.'");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "vn 0 0 one\n", 4), "normal", "'one'");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "vt 0.5 x\n", 4), "texture", "'x'");
}

TEST(ObjReject, WrongNumberCount) {
    EXPECT_CONTAINS_ALL(rejectObj("v 1 2\n", 1), "needs 3 to 7 numbers, found 2");
    EXPECT_CONTAINS_ALL(rejectObj("v 1 2 3 4 5 6 7 8\n", 1), "found 8");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "vn 0 1\n", 4), "needs 3 numbers");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "vt\n", 4), "needs 1 to 3 numbers");
}

TEST(ObjReject, IndexOutOfRange) {
    // tinyobjloader only warns and passes the index through.
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "f 1 2 3\nf 1 2 4\n", 5), "vertex index 4 out of range",
                        "defines 3");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "vn 0 0 1\nf 1//1 2//2 3//1\n", 5),
                        "normal index 2 out of range");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "f 1/1 2/1 3/1\n", 4),
                        "texture coordinate index 1 out of range");
}

TEST(ObjReject, IndexZero) {
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "f 0 1 2\n", 4), "index 0", "start at 1");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "vn 0 0 1\nf 1//0 2//1 3//1\n", 5), "normal index 0");
}

TEST(ObjReject, RelativeIndexBeforeFirstVertex) {
    // tinyobjloader passes these as vertex -1.
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "f -1 -2 -4\n", 4), "relative vertex index -4",
                        "before the first", "3 defined so far");
    // Relative to the vertices defined so far, not in the whole file.
    EXPECT_CONTAINS_ALL(rejectObj("v 0 0 0\nf -1 -2 -3\n" + kTriangle, 2), "relative vertex index -2");
}

TEST(ObjReject, MalformedFaceIndices) {
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "f 1 2 x\n", 4), "'x'");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "f 1 2 3.5\n", 4), "'3.5'");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "f 1/ 2 3\n", 4), "'1/'");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "f 1/1/1/1 2 3\n", 4), "'1/1/1/1'");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "f /1 2 3\n", 4), "'/1'");
    EXPECT_CONTAINS_ALL(rejectObj(kTriangle + "f 1 2 99999999999\n", 4), "'99999999999'");
}

TEST(ObjReject, LineNumbersCountCrlfAndCr) {
    EXPECT_CONTAINS_ALL(rejectObj("v 0 0 0\r\nv 1 0 0\r\nv 0 1 bad\r\n", 3), "'bad'");
    EXPECT_CONTAINS_ALL(rejectObj("v 0 0 0\rv 1 0 0\rv 0 1 bad\r", 3), "'bad'");
}

TEST(ObjReject, NoValidTriangleLeft) {
    std::string degenerate = rejectObj("v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n");
    EXPECT_CONTAINS_ALL(degenerate, "no valid triangle", "1 degenerate");
    std::string nan = rejectObj("v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 1\n");
    EXPECT_CONTAINS_ALL(nan, "no valid triangle", "2 triangles with NaN or infinite");
    std::string shortFaces = rejectObj(kTriangle + "f 1 2\nf 3\n");
    EXPECT_CONTAINS_ALL(shortFaces, "no valid triangle", "2 faces with fewer than 3 vertices");
}

TEST(ObjReject, ErrorsDoNotWarnFirst) {
    WarningCapture capture;
    rejectObj("mtllib missing.mtl\nv 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
}

TEST(ObjReject, UnknownExtensionInLoadScene) {
    test::TempDir dir;
    std::string path = dir.write("picture.png", "v 0 0 0\n");
    EXPECT_CONTAINS_ALL(errorOf([&] { loadScene(path); }), path, "'.png'",
                        "(expected .obj, .gltf, .glb or .json)");
}

}  // namespace
}  // namespace fp
