// glTF through build/fragpath: renders, exit status 1 with the loader's message for bad files, and a
// Cornell-like box that renders the same image bit for bit as a glTF file and as the equivalent OBJ.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "cli/fragpath_runner.h"
#include "image/image.h"
#include "scene/gltf_test_util.h"
#include "scene/load.h"

namespace fp {
namespace {

using json = nlohmann::json;
using test::CliRun;
using test::GltfBuilder;

class GltfCli : public test::TempDirTest {};

// An emissive triangle facing +z (radiance 1) and a camera 3 in front of it.
GltfBuilder litTriangle() {
    GltfBuilder b;
    int p = b.vec3({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}});
    b.material({{"pbrMetallicRoughness", {{"metallicFactor", 0}}}, {"emissiveFactor", {1, 1, 1}}});
    b.mesh(json::array({{{"attributes", {{"POSITION", p}}}, {"material", 0}}}));
    b.push("cameras", {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}});
    b.node({{"mesh", 0}});
    b.node({{"camera", 0}, {"translation", {0, 0, 3}}});
    b.scene({0, 1});
    return b;
}

TEST_F(GltfCli, RendersGltfAndGlbFiles) {
    write("t.gltf", litTriangle().gltf());
    write("t.glb", litTriangle().glb());
    for (const char* file : {"t.gltf", "t.glb"}) {
        CliRun r = test::runFragpath("render " + path(file) +
                                     " --size 16x16 --spp 2 --environment none --quiet -o " + path("t.pfm"));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        Image image = readImage(path("t.pfm"));
        // The camera looks at the emissive triangle: the centre pixel shows its radiance, 1 (with no
        // environment: a lone glowing triangle would otherwise get the studio light, reflected on top).
        EXPECT_FLOAT_EQ(image.at(8, 8).r, 1.0f) << file;
        std::remove(path("t.pfm").c_str());
    }
}

TEST_F(GltfCli, BadFilesExitWithStatusOneAndTheLoadersMessage) {
    json doc = json::parse(litTriangle().gltf());
    doc["nodes"][0]["children"] = {0};
    write("cycle.gltf", doc.dump());
    CliRun r = test::runFragpath("render " + path("cycle.gltf") + " --quiet -o " + path("x.png"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("fragpath: error: " + path("cycle.gltf") + ": nodes[0] is its own ancestor"),
              std::string::npos)
        << r.output;
    write("missing.gltf", litTriangle().gltf("missing.bin"));
    r = test::runFragpath("render " + path("missing.gltf") + " --quiet -o " + path("x.png"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("buffer file 'missing.bin' not found or unreadable"), std::string::npos)
        << r.output;
    write("cut.glb", litTriangle().glb().substr(0, 100));
    r = test::runFragpath("render " + path("cut.glb") + " --quiet -o " + path("x.png"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("cut.glb: not a valid .glb"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(path("x.png")));
}

// A box 2 wide (floor, ceiling, back, red left and green right walls, open at -z), a block on the floor
// and a lamp under the ceiling facing down. Every coordinate is a multiple of 1/8, so the transforms of
// the glTF version are exact and both files hold the same floats.
struct Quad {
    std::array<glm::vec3, 4> p;  // counter-clockwise from the front
    std::string material;
};

std::vector<Quad> roomQuads() {
    return {
        {{{{0, 0, 0}, {0, 0, 2}, {2, 0, 2}, {2, 0, 0}}}, "white"},  // floor, facing +y
        {{{{0, 2, 0}, {2, 2, 0}, {2, 2, 2}, {0, 2, 2}}}, "white"},  // ceiling, facing -y
        {{{{0, 0, 2}, {0, 2, 2}, {2, 2, 2}, {2, 0, 2}}}, "white"},  // back, facing -z
        {{{{0, 0, 0}, {0, 2, 0}, {0, 2, 2}, {0, 0, 2}}}, "red"},    // left, facing +x
        {{{{2, 0, 0}, {2, 0, 2}, {2, 2, 2}, {2, 2, 0}}}, "green"},  // right, facing -x
    };
}

// The lamp in its node's frame (the node moves it to (1, 1.875, 1)) and in the world.
const std::array<glm::vec3, 4> kLampLocal = {
    {{-0.25f, 0, -0.25f}, {0.25f, 0, -0.25f}, {0.25f, 0, 0.25f}, {-0.25f, 0, 0.25f}}};
glm::vec3 lampWorld(glm::vec3 p) {
    return p + glm::vec3(1, 1.875f, 1);
}

// The block: a unit cube (Box faces) scaled by (0.5, 1, 0.5), turned 180 degrees about +y and moved to
// (1.25, 0.5, 1.125); its normals are given.
struct Face {
    std::array<glm::vec3, 4> p;
    glm::vec3 n;
};
std::vector<Face> cubeFaces() {
    std::vector<Face> faces;
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : axes) {
        glm::vec3 u = std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        glm::vec3 v = glm::cross(n, u);
        Face f{{0.5f * (n - u - v), 0.5f * (n + u - v), 0.5f * (n + u + v), 0.5f * (n - u + v)}, n};
        faces.push_back(f);
    }
    return faces;
}
glm::vec3 blockWorld(glm::vec3 p) {
    return glm::vec3(-0.5f * p.x, p.y, -0.5f * p.z) + glm::vec3(1.25f, 0.5f, 1.125f);
}
glm::vec3 blockNormal(glm::vec3 n) {
    return glm::vec3(-n.x, n.y, -n.z);  // the inverse transpose keeps axis directions, turned
}

std::string objNumber(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(v));
    return text;
}
std::string objVec(const char* tag, glm::vec3 v) {
    return std::string(tag) + " " + objNumber(v.x) + " " + objNumber(v.y) + " " + objNumber(v.z) + "\n";
}

TEST_F(GltfCli, CornellLikeBoxRendersTheSameImageAsTheEquivalentObj) {
    // Both formats give the one metallic-roughness model: metallic 0, roughness 1 (glTF's default).
    const char* mtl =
        "newmtl white\nKd 0.73 0.73 0.73\nPm 0\nPr 1\n"
        "newmtl red\nKd 0.63 0.065 0.05\nPm 0\nPr 1\n"
        "newmtl green\nKd 0.14 0.45 0.091\nPm 0\nPr 1\n"
        "newmtl lamp\nKd 0 0 0\nKe 16 12 4\nPm 0\nPr 1\n";
    auto gltfMaterial = [](double r, double g, double b) {
        return json{{"pbrMetallicRoughness", {{"baseColorFactor", {r, g, b, 1.0}}, {"metallicFactor", 0.0}}},
                    {"doubleSided", true}};  // as OBJ faces are
    };

    // The OBJ: the same triangles in the same order (walls, block, lamp), each quad as (0 1 2) (0 2 3).
    std::string obj = "mtllib room.mtl\n";
    int vertices = 0, normals = 0;
    auto objQuad = [&](const std::array<glm::vec3, 4>& p, const glm::vec3* n) {
        for (const glm::vec3& v : p) obj += objVec("v", v);
        int a = vertices + 1;
        vertices += 4;
        if (n) {
            obj += objVec("vn", *n);
            int m = ++normals;
            auto c = [&](int k) { return std::to_string(a + k) + "//" + std::to_string(m); };
            obj += "f " + c(0) + " " + c(1) + " " + c(2) + "\nf " + c(0) + " " + c(2) + " " + c(3) + "\n";
        } else {
            auto c = [&](int k) { return std::to_string(a + k); };
            obj += "f " + c(0) + " " + c(1) + " " + c(2) + "\nf " + c(0) + " " + c(2) + " " + c(3) + "\n";
        }
    };
    for (const Quad& q : roomQuads()) {
        obj += "usemtl " + q.material + "\n";
        objQuad(q.p, nullptr);
    }
    obj += "usemtl white\n";
    for (const Face& f : cubeFaces()) {
        std::array<glm::vec3, 4> world;
        for (int k = 0; k < 4; ++k) world[size_t(k)] = blockWorld(f.p[size_t(k)]);
        glm::vec3 n = blockNormal(f.n);
        objQuad(world, &n);
    }
    obj += "usemtl lamp\n";
    std::array<glm::vec3, 4> lamp;
    for (int k = 0; k < 4; ++k) lamp[size_t(k)] = lampWorld(kLampLocal[size_t(k)]);
    objQuad(lamp, nullptr);

    // The glTF: walls in one mesh, one primitive per material (indexed 16-bit, the red wall without
    // indices), the block and the lamp placed by nodes under a root, a camera turned to look along +z.
    GltfBuilder b;
    int white = b.material(gltfMaterial(0.73, 0.73, 0.73));
    int red = b.material(gltfMaterial(0.63, 0.065, 0.05));
    int green = b.material(gltfMaterial(0.14, 0.45, 0.091));
    json lampMaterial = gltfMaterial(0, 0, 0);
    lampMaterial["emissiveFactor"] = {1.0, 0.75, 0.25};
    lampMaterial["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", 16.0}}}};
    int lampMat = b.material(lampMaterial);
    json walls = json::array();
    std::vector<Quad> room = roomQuads();
    std::vector<glm::vec3> whites;
    for (const Quad& q : room)
        if (q.material == "white") whites.insert(whites.end(), q.p.begin(), q.p.end());
    std::vector<uint16_t> whiteIndices;
    for (uint16_t q = 0; q < 3; ++q)
        for (uint16_t k : {0, 1, 2, 0, 2, 3}) whiteIndices.push_back(uint16_t(4 * q + k));
    walls.push_back({{"attributes", {{"POSITION", b.vec3(whites)}}},
                     {"indices", b.indices16(whiteIndices)},
                     {"material", white}});
    const std::array<glm::vec3, 4>& left = room[3].p;
    walls.push_back(
        {{"attributes", {{"POSITION", b.vec3({left[0], left[1], left[2], left[0], left[2], left[3]})}}},
         {"material", red}});
    const std::array<glm::vec3, 4>& right = room[4].p;
    walls.push_back({{"attributes", {{"POSITION", b.vec3({right[0], right[1], right[2], right[3]})}}},
                     {"indices", b.indices32({0, 1, 2, 0, 2, 3})},
                     {"material", green}});
    int wallMesh = b.mesh(walls);
    std::vector<glm::vec3> cubeP, cubeN;
    std::vector<uint16_t> cubeI;
    for (const Face& f : cubeFaces()) {
        uint16_t first = uint16_t(cubeP.size());
        for (const glm::vec3& v : f.p) {
            cubeP.push_back(v);
            cubeN.push_back(f.n);
        }
        for (uint16_t k : {0, 1, 2, 0, 2, 3}) cubeI.push_back(uint16_t(first + k));
    }
    int blockMesh =
        b.mesh(json::array({{{"attributes", {{"POSITION", b.vec3(cubeP)}, {"NORMAL", b.vec3(cubeN)}}},
                             {"indices", b.indices16(cubeI)},
                             {"material", white}}}));
    int lampMesh =
        b.mesh(json::array({{{"attributes", {{"POSITION", b.vec3({kLampLocal.begin(), kLampLocal.end()})}}},
                             {"indices", b.indices16({0, 1, 2, 0, 2, 3})},
                             {"material", lampMat}}}));
    constexpr double kPi = 3.14159265358979323846;
    b.push("cameras",
           {{"type", "perspective"}, {"perspective", {{"yfov", 40.0 * kPi / 180.0}, {"znear", 0.01}}}});
    b.node({{"children", {1, 2, 3}}});
    b.node({{"mesh", wallMesh}});
    b.node({{"mesh", blockMesh},
            {"translation", {1.25, 0.5, 1.125}},
            {"rotation", {0, 1, 0, 0}},
            {"scale", {0.5, 1, 0.5}}});
    b.node({{"mesh", lampMesh}, {"translation", {1, 1.875, 1}}});
    b.node({{"camera", 0}, {"translation", {1, 1, -3.5}}, {"rotation", {0, 1, 0, 0}}});
    b.scene({0, 4});

    write("room.mtl", mtl);
    write("room.obj", obj);
    std::string gltf = write("room.gltf", b.gltf());
    // The camera the glTF's gives: at (1, 1, -3.5) looking along +z, the target at the depth of the
    // box's centre, a 40 degree field of view. The OBJ gets it from its scene file.
    Scene loaded = loadScene(gltf);
    ASSERT_TRUE(loaded.camera.has_value());
    EXPECT_EQ(loaded.camera->eye, glm::vec3(1, 1, -3.5f));
    EXPECT_EQ(loaded.camera->target, glm::vec3(1, 1, 1));
    EXPECT_EQ(loaded.camera->up, glm::vec3(0, 1, 0));
    EXPECT_EQ(loaded.camera->fovY, 40.0f);
    write(
        "room.json",
        R"({"mesh": "room.obj", "camera": {"eye": [1, 1, -3.5], "target": [1, 1, 1], "up": [0, 1, 0], "fov": 40}})");

    const std::string settings = " --size 48x48 --spp 8 --seed 11 --max-depth 4 --quiet -o ";
    CliRun fromGltf = test::runFragpath("render " + gltf + settings + path("gltf.pfm"));
    ASSERT_EQ(fromGltf.exitCode, 0) << fromGltf.output;
    EXPECT_EQ(fromGltf.output, "") << "no warnings";
    CliRun fromObj = test::runFragpath("render " + path("room.json") + settings + path("obj.pfm"));
    ASSERT_EQ(fromObj.exitCode, 0) << fromObj.output;
    Image a = readImage(path("gltf.pfm")), o = readImage(path("obj.pfm"));
    ASSERT_EQ(a.pixels.size(), o.pixels.size());
    size_t differing = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            differing += std::memcmp(&a.pixels[i][c], &o.pixels[i][c], sizeof(float)) != 0;
    EXPECT_EQ(differing, 0u) << "of " << 3 * a.pixels.size() << " values";
    // And it is a lit room, not two equally black images.
    double sum = 0.0;
    for (const glm::vec3& v : a.pixels) sum += double(v.r + v.g + v.b) / 3.0;
    EXPECT_GT(sum / double(a.pixels.size()), 0.05);
}

}  // namespace
}  // namespace fp
