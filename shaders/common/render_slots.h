/* Binding points and constants shared by the renderer (src/render) and the render shaders
 * (shaders/render). Valid C and GLSL: only #define lines. The render state guard saves
 * exactly the texture units 0..PF_RENDER_TEX_UNITS-1 and image units
 * 0..PF_RENDER_IMAGE_UNITS-1, so every binding below must stay inside those ranges. */
#ifndef PF_RENDER_SLOTS_H
#define PF_RENDER_SLOTS_H

/* uniform block with the camera and look of one render call (common/render.glsl,
 * src/render/render_uniforms.h); binding 0 belongs to the simulation's block */
#define PF_UBO_RENDER 1

/* texture units (sampler bindings) */
#define PF_TEX_SCENE_COLOR 0   /* copy of the engine's scene colour (the engine's own during the copy) */
#define PF_TEX_SCENE_DEPTH 1   /* the engine's scene depth as eye depth (the engine's own window depth
                                  during the copy) */
#define PF_TEX_LIQUID_DEPTH 2  /* linear eye depth of the liquid surface (filter input / shading) */
#define PF_TEX_THICKNESS 3     /* liquid thickness along the view ray, metres */
#define PF_TEX_ENVIRONMENT 4   /* the engine's environment cube map */
#define PF_TEX_SHADED_COLOR 5  /* shaded liquid colour, alpha 1 where there is liquid */
#define PF_TEX_SHADED_DEPTH 6  /* liquid window depth in the engine's convention */
#define PF_TEX_SCENE_DEPTH_TILES 7  /* the nearest scene eye depth per PF_RENDER_TILE tile */
#define PF_RENDER_TEX_UNITS 8

/* image units (compute path) */
#define PF_IMG_SMOOTH_OUT 0
#define PF_IMG_SHADE_COLOR 0
#define PF_IMG_SHADE_DEPTH 1
#define PF_IMG_SPLAT_DEPTH 0      /* r32ui: nearest eye depth as float bits */
#define PF_IMG_SPLAT_THICKNESS 1  /* r32ui: thickness in fixed point */
#define PF_IMG_RAW_DEPTH 2        /* r32f outputs of the splat resolve */
#define PF_IMG_THICKNESS 3
#define PF_IMG_SCENE_COLOR 0      /* the scene copy's outputs: rgba16f colour, r32f window depth */
#define PF_IMG_SCENE_DEPTH 1
#define PF_IMG_SCENE_DEPTH_TILES 2 /* and the nearest eye depth of each PF_RENDER_TILE tile (r32f) */
#define PF_RENDER_IMAGE_UNITS 4

/* storage block of the compute splats: the simulation's particle positions */
#define PF_SSBO_PARTICLE_POS 0
/* and the simulation's live-count record (common/slots.h PF_COUNT_*): the dispatch covers every
 * particle slot in use, the record says how many are live (emitters and sinks decide on the GPU) */
#define PF_SSBO_PARTICLE_COUNT 1
/* and its particle count per cell (the spray test of common/ssf_spray.glsl) */
#define PF_SSBO_CELL_COUNT 2
/* and the live particle slots in the P2G's tile order, which the compute splat walks when
 * PF_LOC_SPLAT_ORDERED is 1 */
#define PF_SSBO_PARTICLE_ORDER 3
/* the liquid surface's tile list (compute path): a glDrawArraysIndirect record (uints 0-3: 6
 * vertices, one instance per tile), a glDispatchComputeIndirect record (uints 4-6: at least one
 * workgroup per tile, in rows of at most PF_TILES_ROW), then from uint PF_TILES_HEADER the
 * PF_RENDER_TILE tiles holding liquid (x | y << 16), which the splat resolve lists and SHADE and
 * RESOLVE cover instead of the whole screen */
#define PF_SSBO_LIQUID_TILES 4
#define PF_TILES_DISPATCH 4
#define PF_TILES_HEADER 8
/* workgroups per row of SHADE's dispatch: GL promises 65535 along x */
#define PF_TILES_ROW 65535u
/* invocations per workgroup of the compute splats (one particle each) */
#define PF_SPLAT_WORKGROUP 64
/* thickness fixed point: 2^16 per metre (15 um steps, 65 km range) */
#define PF_THICKNESS_FIXED_SCALE 65536.0
/* splat depth image value where no sphere covers a pixel: the bits of +infinity */
#define PF_SPLAT_NO_DEPTH_BITS 0x7F800000u

/* vertex attributes of the sphere sprites: one vec4 per particle (instanced) */
#define PF_ATTR_POSITION 0
#define PF_ATTR_VELOCITY 1

/* varying locations between render/sphere.vert and its fragment shaders */
#define PF_VARY_THROUGH 0
#define PF_VARY_CENTER 1
#define PF_VARY_VALUE 2

/* explicit uniform locations */
#define PF_LOC_SMOOTH_DIRECTION 0 /* ivec2: (1,0) horizontal pass, (0,1) vertical pass */
#define PF_LOC_SPLAT_COUNT 0      /* uint: particles to splat */
#define PF_LOC_SPLAT_ORDERED 1    /* uint: 1 = walk them in PF_SSBO_PARTICLE_ORDER's order */

/* compute tiles of the screen-space passes */
#define PF_RENDER_TILE 8

/* values of pf.h enums used by shaders (static_assert'ed equal in src/render) */
#define PF_SSF_FILTER_BILATERAL_ID 0
#define PF_SSF_FILTER_NARROW_RANGE_ID 1
#define PF_DEPTH_STANDARD_ID 0
#define PF_DEPTH_ZERO_TO_ONE_ID 1
#define PF_DEPTH_REVERSED_Z_ID 2
#define PF_COLOR_SPEED_ID 0
#define PF_COLOR_VELOCITY_X_ID 1
#define PF_COLOR_VELOCITY_Y_ID 2
#define PF_COLOR_VELOCITY_Z_ID 3
#define PF_COLOR_HEIGHT_ID 4
#define PF_COLOR_UNIFORM_ID 5

/* linear eye depth stored where a pixel holds no liquid (real depths are >= near > 0) */
#define PF_NO_LIQUID 0.0

#endif
