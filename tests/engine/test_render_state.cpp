// GL etiquette and the C boundary of rendering: every render call (succeeding or rejected)
// leaves the engine's GL state as it found it, even hostile raster state, and draws the same
// image under it as under a clean state; bad arguments are refused with a message naming the
// field and nothing drawn; render timings reach pf_get_stats; pf_destroy frees the renderer's
// GL objects.
#include <cstring>
#include <string>
#include <vector>

#include "support/render_fixture.h"

namespace pf::test {
namespace {

class RenderState : public RenderTest {};

std::vector<float> block() {
    std::vector<float> xyz;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 6; ++j)
            for (int i = 0; i < 8; ++i) xyz.insert(xyz.end(), {0.5f + 0.06f * i, 0.6f + 0.06f * j, 0.9f - 0.06f * k});
    return xyz;
}

TEST_F(RenderState, EveryRenderCallRestoresEngineState) {
    add(block());
    EngineTarget t(96, 64, GL_RGBA16F);
    const int vp[4] = {0, 0, 96, 64};
    const TestCamera c = camera(vp);
    GLuint cube = 0;
    glGenTextures(1, &cube);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_RGBA8, 2, 2);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    auto reset_target = [&] {
        t.write_color(checkerboard(t.width, t.height, 8));
        t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
    };
    auto render = [&](pf_ssf_path path, pf_ssf_filter filter) {
        pf_ssf_params p = pf_default_ssf_params();
        p.path = path;
        p.filter = filter;
        const pf_render_target target{t.fbo, t.color, t.depth, cube};
        EXPECT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, &p), PF_OK) << last_log();
    };
    Engine engine(EngineProgram::graphics);
    int v = 0;
    for (pf_ssf_path path : {PF_SSF_PATH_COMPUTE, PF_SSF_PATH_RASTER}) {
        for (pf_ssf_filter filter : {PF_SSF_FILTER_BILATERAL, PF_SSF_FILTER_NARROW_RANGE, PF_SSF_FILTER_NONE}) {
            const std::string what = "pf_render_ssf path " + std::to_string(path) + " filter " + std::to_string(filter);
            engine.unbind_all();
            reset_target();
            render(path, filter);  // the reference image, under a clean GL state
            const std::vector<float> clean = t.read_color();
            reset_target();
            guarded_call(engine, v++, what.c_str(), [&] { render(path, filter); });
            engine.unbind_all();
            EXPECT_EQ(std::memcmp(t.read_color().data(), clean.data(), clean.size() * 4), 0)
                << what << ": the engine's GL state changed the image";
        }
    }
    const pf_render_target sprites{t.fbo, 0, 0, 0};
    guarded_call(engine, v++, "pf_render_particles", [&] {
        EXPECT_EQ(pf_render_particles(sim_.get(), &c.cam, &sprites, nullptr), PF_OK) << last_log();
    });
    guarded_call(engine, v++, "pf_render_ssf without scene depth", [&] {
        const pf_render_target no_depth{t.fbo, t.color, 0, 0};
        EXPECT_EQ(pf_render_ssf(sim_.get(), &c.cam, &no_depth, nullptr), PF_OK) << last_log();
    });
    pf_stats st{};
    guarded_call(engine, v++, "pf_get_stats after rendering", [&] { EXPECT_EQ(pf_get_stats(sim_.get(), &st), PF_OK); });
    guarded_call(engine, v++, "pf_render_ssf rejected (NULL camera)", [&] {
        const pf_render_target target{t.fbo, t.color, t.depth, 0};
        EXPECT_EQ(pf_render_ssf(sim_.get(), nullptr, &target, nullptr), PF_ERROR_INVALID_ARGUMENT);
    });
    guarded_call(engine, v++, "pf_render_ssf rejected (scene colour is a cube map)", [&] {
        const pf_render_target target{t.fbo, cube, t.depth, 0};
        EXPECT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, nullptr), PF_ERROR_INVALID_ARGUMENT);
    });
    engine.unbind_all();
    glDeleteTextures(1, &cube);
}

// Each bad argument: PF_ERROR_INVALID_ARGUMENT, a message naming the field, and the target's
// colour and depth untouched.
TEST_F(RenderState, BadArgumentsAreRefusedAndDrawNothing) {
    add(block());
    EngineTarget t(64, 48, GL_RGBA8);
    t.write_color(checkerboard(t.width, t.height, 4));
    t.write_depth(std::vector<float>(size_t(t.width) * t.height, 1.0f));
    const int vp[4] = {0, 0, 64, 48};
    const TestCamera good = camera(vp);
    const std::vector<float> color0 = t.read_color(), depth0 = t.read_depth();

    // GL objects that are not what they claim.
    GLuint ms = 0, depth_tex = 0, int_tex = 0, small = 0, empty_fbo = 0, empty_tex = 0, buffer = 0;
    glGenTextures(1, &ms);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, ms);
    glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8, 64, 48, GL_TRUE);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    glGenTextures(1, &depth_tex);
    glBindTexture(GL_TEXTURE_2D, depth_tex);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT24, 64, 48);
    glGenTextures(1, &int_tex);
    glBindTexture(GL_TEXTURE_2D, int_tex);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8UI, 64, 48);
    glGenTextures(1, &small);
    glBindTexture(GL_TEXTURE_2D, small);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 32, 48);
    glGenTextures(1, &empty_tex);
    glBindTexture(GL_TEXTURE_2D, empty_tex);  // a texture object without an image
    glBindTexture(GL_TEXTURE_2D, 0);
    // A depth-stencil texture sampled as stencil, and a colour texture whose base level is 1: the
    // scene copy fetches level 0's depth.
    GLuint stencil_tex = 0, based = 0;
    glGenTextures(1, &stencil_tex);
    glBindTexture(GL_TEXTURE_2D, stencil_tex);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH24_STENCIL8, 64, 48);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
    glGenTextures(1, &based);
    glBindTexture(GL_TEXTURE_2D, based);
    glTexStorage2D(GL_TEXTURE_2D, 2, GL_RGBA8, 64, 48);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &empty_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, empty_fbo);  // no attachments: incomplete
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGenBuffers(1, &buffer);

    struct Case {
        const char* what;
        const char* field;  // must appear in the logged message
        pf_camera cam;
        pf_render_target target;
        pf_ssf_params params;
    };
    const pf_render_target ok_target{t.fbo, t.color, t.depth, 0};
    const pf_ssf_params ok = pf_default_ssf_params();
    std::vector<Case> cases;
    auto with_cam = [&](const char* what, const char* field, auto&& edit) {
        Case k{what, field, good.cam, ok_target, ok};
        edit(k.cam);
        cases.push_back(k);
    };
    auto with_params = [&](const char* what, const char* field, auto&& edit) {
        Case k{what, field, good.cam, ok_target, ok};
        edit(k.params);
        cases.push_back(k);
    };
    auto with_target = [&](const char* what, const char* field, pf_render_target target) {
        cases.push_back(Case{what, field, good.cam, target, ok});
    };
    with_cam("NaN in view", "camera->view", [](pf_camera& c) { c.view[5] = NAN; });
    with_cam("Inf in proj", "camera->proj", [](pf_camera& c) { c.proj[0] = INFINITY; });
    with_cam("singular proj", "camera->proj", [](pf_camera& c) { std::memset(c.proj, 0, sizeof c.proj); });
    with_cam("viewport width 0", "camera->viewport", [](pf_camera& c) { c.viewport[2] = 0; });
    with_cam("viewport height 16385", "camera->viewport", [](pf_camera& c) { c.viewport[3] = 16385; });
    with_cam("viewport x -1", "camera->viewport", [](pf_camera& c) { c.viewport[0] = -1; });
    with_cam("near 0", "camera->near_plane", [](pf_camera& c) { c.near_plane = 0.0f; });
    with_cam("far below near", "camera->far_plane", [](pf_camera& c) { c.far_plane = 0.05f; });
    with_cam("unknown convention", "camera->depth_convention",
             [](pf_camera& c) { c.depth_convention = pf_depth_convention(7); });
    with_cam("viewport beyond the scene texture", "target->scene_color", [](pf_camera& c) { c.viewport[0] = 8; });
    with_params("negative radius", "params->particle_radius", [](pf_ssf_params& p) { p.particle_radius = -1.0f; });
    with_params("unknown filter", "params->filter", [](pf_ssf_params& p) { p.filter = pf_ssf_filter(9); });
    with_params("filter radius 65", "params->filter_radius", [](pf_ssf_params& p) { p.filter_radius = 65; });
    with_params("17 iterations", "params->filter_iterations", [](pf_ssf_params& p) { p.filter_iterations = 17; });
    with_params("NaN depth range", "params->filter_depth_range", [](pf_ssf_params& p) { p.filter_depth_range = NAN; });
    with_params("negative absorption", "params->absorption", [](pf_ssf_params& p) { p.absorption[1] = -0.1f; });
    with_params("refraction 2", "params->refraction", [](pf_ssf_params& p) { p.refraction = 2.0f; });
    with_params("fresnel 1.5", "params->fresnel_f0", [](pf_ssf_params& p) { p.fresnel_f0 = 1.5f; });
    with_params("negative specular", "params->specular", [](pf_ssf_params& p) { p.specular = -1.0f; });
    with_params("shininess 0.5", "params->shininess", [](pf_ssf_params& p) { p.shininess = 0.5f; });
    with_params("zero light", "params->light_direction", [](pf_ssf_params& p) { std::memset(p.light_direction, 0, 12); });
    with_params("unknown path", "params->path", [](pf_ssf_params& p) { p.path = pf_ssf_path(3); });
    with_params("negative world filter radius", "params->filter_world_radius",
                [](pf_ssf_params& p) { p.filter_world_radius = -0.1f; });
    with_params("NaN world filter radius", "params->filter_world_radius",
                [](pf_ssf_params& p) { p.filter_world_radius = NAN; });
    with_params("negative spray scale", "params->spray_radius_scale",
                [](pf_ssf_params& p) { p.spray_radius_scale = -0.5f; });
    with_params("spray scale 1.5", "params->spray_radius_scale", [](pf_ssf_params& p) { p.spray_radius_scale = 1.5f; });
    with_params("NaN spray scale", "params->spray_radius_scale", [](pf_ssf_params& p) { p.spray_radius_scale = NAN; });
    with_target("framebuffer not an FBO", "target->framebuffer", {12345, t.color, t.depth, 0});
    with_target("incomplete framebuffer", "target->framebuffer", {empty_fbo, t.color, t.depth, 0});
    with_target("no scene colour", "target->scene_color", {t.fbo, 0, t.depth, 0});
    with_target("scene colour is a buffer name", "target->scene_color", {t.fbo, buffer, t.depth, 0});
    with_target("scene colour multisampled", "target->scene_color", {t.fbo, ms, t.depth, 0});
    with_target("scene colour a depth texture", "target->scene_color", {t.fbo, depth_tex, t.depth, 0});
    with_target("scene colour integer", "target->scene_color", {t.fbo, int_tex, t.depth, 0});
    with_target("scene colour smaller than the viewport", "target->scene_color", {t.fbo, small, t.depth, 0});
    with_target("scene colour without image", "target->scene_color", {t.fbo, empty_tex, t.depth, 0});
    with_target("scene depth a colour texture", "target->scene_depth", {t.fbo, t.color, small, 0});
    with_target("scene depth sampled as stencil", "target->scene_depth", {t.fbo, t.color, stencil_tex, 0});
    with_target("scene colour from base level 1", "target->scene_color", {t.fbo, based, t.depth, 0});
    with_target("environment a 2D texture", "target->environment_cubemap", {t.fbo, t.color, t.depth, t.color});

    for (const Case& k : cases) {
        SCOPED_TRACE(k.what);
        clear_log();
        EXPECT_EQ(pf_render_ssf(sim_.get(), &k.cam, &k.target, &k.params), PF_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(last_log()).find(k.field), std::string::npos) << "message: " << last_log();
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
    EXPECT_EQ(pf_render_ssf(nullptr, &good.cam, &ok_target, nullptr), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(pf_render_ssf(sim_.get(), &good.cam, nullptr, nullptr), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(last_log()).find("target"), std::string::npos);
    pf_particle_params pp = pf_default_particle_params();
    pp.range[1] = pp.range[0];
    EXPECT_EQ(pf_render_particles(sim_.get(), &good.cam, &ok_target, &pp), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(last_log()).find("params->range"), std::string::npos);
    pp = pf_default_particle_params();
    pp.color_by = pf_particle_color(6);
    EXPECT_EQ(pf_render_particles(sim_.get(), &good.cam, &ok_target, &pp), PF_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(last_log()).find("params->color_by"), std::string::npos);

    EXPECT_EQ(std::memcmp(t.read_color().data(), color0.data(), color0.size() * 4), 0) << "a refused call drew colour";
    EXPECT_EQ(std::memcmp(t.read_depth().data(), depth0.data(), depth0.size() * 4), 0) << "a refused call drew depth";
    // The same target is fine with good arguments (the refusals were about the arguments).
    EXPECT_EQ(pf_render_ssf(sim_.get(), &good.cam, &ok_target, nullptr), PF_OK) << last_log();
    const GLuint textures[] = {ms, depth_tex, int_tex, small, empty_tex, stencil_tex, based};
    glDeleteTextures(7, textures);
    glDeleteFramebuffers(1, &empty_fbo);
    glDeleteBuffers(1, &buffer);
}

TEST_F(RenderState, RenderTimingsReachStats) {
    add(block());
    EngineTarget t(64, 48, GL_RGBA8);
    const int vp[4] = {0, 0, 64, 48};
    const TestCamera c = camera(vp);
    const pf_render_target target{t.fbo, t.color, t.depth, 0};
    pf_stats st{};
    ASSERT_EQ(pf_get_stats(sim_.get(), &st), PF_OK);
    EXPECT_EQ(st.render_frame, 0u) << "no render call yet";
    ASSERT_EQ(pf_render_ssf(sim_.get(), &c.cam, &target, nullptr), PF_OK) << last_log();
    glFinish();
    ASSERT_EQ(pf_get_stats(sim_.get(), &st), PF_OK);
    EXPECT_EQ(st.render_frame, 1u);
    EXPECT_GT(st.render_cpu_ms, 0.0f);
    float sum = 0.0f;
    for (int p = 0; p < PF_RENDER_PASS_COUNT; ++p) {
        EXPECT_GE(st.render_gpu_ms[p], 0.0f) << pf_render_pass_name(pf_render_pass(p));
        sum += st.render_gpu_ms[p];
    }
    EXPECT_GT(st.render_gpu_ms[PF_RENDER_PASS_THICKNESS] + st.render_gpu_ms[PF_RENDER_PASS_SHADE], 0.0f);
    EXPECT_EQ(st.render_gpu_ms[PF_RENDER_PASS_PARTICLES], 0.0f) << "no particle view in this call";
    EXPECT_FLOAT_EQ(st.render_gpu_total_ms, sum);
    ASSERT_EQ(pf_render_particles(sim_.get(), &c.cam, &target, nullptr), PF_OK) << last_log();
    glFinish();
    ASSERT_EQ(pf_get_stats(sim_.get(), &st), PF_OK);
    EXPECT_EQ(st.render_frame, 2u);
    EXPECT_GT(st.render_gpu_ms[PF_RENDER_PASS_PARTICLES], 0.0f);
    EXPECT_EQ(st.render_gpu_ms[PF_RENDER_PASS_SHADE], 0.0f) << "the particle view has no shade pass";
    EXPECT_STREQ(pf_render_pass_name(PF_RENDER_PASS_SMOOTH), "smooth");
    EXPECT_STREQ(pf_render_pass_name(PF_RENDER_PASS_COUNT), "unknown");
}

// pf_destroy frees the renderer's programs, textures, framebuffers, samplers, VAO and buffers.
TEST_F(RenderState, DestroyFreesRendererObjects) {
    EngineTarget t(64, 48, GL_RGBA8);
    const int vp[4] = {0, 0, 64, 48};
    const TestCamera c = camera(vp);
    const pf_render_target target{t.fbo, t.color, t.depth, 0};
    // A deleted program the driver still references internally (Mesa keeps the last one drawn
    // with until the next draw) reports GL_DELETE_STATUS true: deleted, not leaked.
    auto live = [] {
        int n = 0;
        for (GLuint name = 1; name < 4096; ++name) {
            GLint deleted = GL_FALSE;
            if (glIsProgram(name)) glGetProgramiv(name, GL_DELETE_STATUS, &deleted);
            n += glIsTexture(name) + glIsFramebuffer(name) + glIsSampler(name) + glIsVertexArray(name) +
                 (glIsProgram(name) && !deleted) + glIsBuffer(name) + glIsQuery(name);
        }
        return n;
    };
    sim_.reset();
    const int before = live();
    for (int round = 0; round < 3; ++round) {
        pf_sim_desc d = test_desc(8, 8, 8, 0.2f);
        SimPtr s = create(d);
        ASSERT_TRUE(s);
        const std::vector<float> xyz = block();
        ASSERT_EQ(pf_add_particles(s.get(), xyz.data(), nullptr, uint32_t(xyz.size() / 3)), PF_OK);
        const int unrendered = live();
        pf_ssf_params p = pf_default_ssf_params();
        p.path = round % 2 ? PF_SSF_PATH_RASTER : PF_SSF_PATH_COMPUTE;
        p.filter = round == 2 ? PF_SSF_FILTER_NARROW_RANGE : PF_SSF_FILTER_BILATERAL;
        ASSERT_EQ(pf_render_ssf(s.get(), &c.cam, &target, &p), PF_OK) << last_log();
        ASSERT_EQ(pf_render_particles(s.get(), &c.cam, &target, nullptr), PF_OK) << last_log();
        EXPECT_GT(live(), unrendered + 15) << "the renderer made its objects (textures, framebuffers, programs...)";
    }
    EXPECT_EQ(live(), before) << "GL objects outlived pf_destroy";
}

}  // namespace
}  // namespace pf::test
