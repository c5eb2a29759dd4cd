# CTest driver of the pf_viewer smoke test: runs the viewer under xvfb-run for a few frames with
# --screenshot, then checks the picture with pf_png_check.
#   -DXVFB_RUN=... -DVIEWER=... -DCHECK=... -DOUT=path.png -DSIZE=WxH -DSCENES=dir
#   [-DEXTRA="--solver mgpcg ..."]  more viewer options, space-separated
include("${CMAKE_CURRENT_LIST_DIR}/require_defined.cmake")
pf_require_defined(viewer_smoke.cmake XVFB_RUN VIEWER CHECK OUT SIZE)
file(REMOVE "${OUT}")
set(ENV{PF_SCENES_DIR} "${SCENES}")
separate_arguments(extra UNIX_COMMAND "${EXTRA}")
execute_process(
  COMMAND "${XVFB_RUN}" -a -s "-screen 0 1280x720x24"
          "${VIEWER}" --scene dam_break_small --size ${SIZE} --frames 6 --screenshot "${OUT}" ${extra}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pf_viewer under xvfb-run failed (${rc})")
endif()
execute_process(COMMAND "${CHECK}" "${OUT}" ${SIZE} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the viewer's screenshot ${OUT} failed the check")
endif()
