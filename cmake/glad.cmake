# Generates GL 4.3 core loaders with glad2 at configure time (offline: --reproducible uses the
# Khronos XML bundled in the pinned glad2 package).
#   pf_glad_mx  — multi-context loader for the library: function pointers live in a
#                 GladGLContext owned by each simulation; no global GL symbols. Built with
#                 hidden visibility so libpflip exports none of it.
#   pf_glad_app — ordinary global loader (gladLoadGL) for samples and tests, standing in for
#                 the engine's own GLAD: linking both proves they do not clash.
find_package(Python3 REQUIRED COMPONENTS Interpreter)

set(PF_GLAD_EXTENSIONS "GL_KHR_debug,GL_NV_shader_atomic_float,GL_ARB_gl_spirv,GL_ARB_buffer_storage")

function(pf_generate_glad name out_dir extra_args)
  set(stamp "${out_dir}/stamp.txt")
  set(args --api gl:core=4.3 --extensions ${PF_GLAD_EXTENSIONS} --out-path ${out_dir}
           --reproducible --quiet c ${extra_args})
  string(REPLACE ";" " " args_str "${args}")
  set(need TRUE)
  if(EXISTS "${stamp}")
    file(READ "${stamp}" old)
    if(old STREQUAL args_str)
      set(need FALSE)
    endif()
  endif()
  if(need)
    message(STATUS "glad2: generating ${name}")
    execute_process(COMMAND ${Python3_EXECUTABLE} -m glad ${args}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "glad2 generation failed (is glad2 installed? run scripts/setup.sh)\n${out}\n${err}")
    endif()
    file(WRITE "${stamp}" "${args_str}")
  endif()
  add_library(${name} STATIC "${out_dir}/src/gl.c")
  target_include_directories(${name} SYSTEM PUBLIC "${out_dir}/include")
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON
                        C_VISIBILITY_PRESET hidden)
endfunction()

pf_generate_glad(pf_glad_mx "${PROJECT_BINARY_DIR}/glad_mx" "--mx")
# Only the samples and tests stand in for an engine; a parent project has its own loader.
if(PF_BUILD_SAMPLES OR PF_BUILD_TESTS)
  pf_generate_glad(pf_glad_app "${PROJECT_BINARY_DIR}/glad_app" "")
endif()
