# CTest driver: pf_viewer under xvfb-run drags an obstacle with the mouse (--drag-obstacle I,DX,DY,
# F0,F1: pressed on obstacle I's centre, the cursor moved DX,DY window pixels over frames F0..F1,
# released after), then checks what it prints at exit:
#  - the run is clean: exit status 0, nothing on stderr that says error, a sane screenshot;
#  - obstacle I moved, is at rest again (velocity zeroed on release), the others did not move;
#  - its centre follows the cursor on screen. The grabbed surface point moves in the camera-facing
#    plane through it, so it stays exactly under the cursor; the centre lies up to RADIUS further
#    along the view (depth D), so it moves on screen by the drag times z_hit / D, which is off by
#    at most |drag| * RADIUS / D pixels. Tolerance: that bound (with |DX| + |DY| for |drag|) plus
#    1 px for the printed whole pixels.
#   -DXVFB_RUN=... -DVIEWER=... -DCHECK=pf_png_check -DOUT=path.png -DSIZE=WxH -DSCENES=dir
#   -DSCENE=name -DOBSTACLE=I -DDX=px -DDY=px -DFIRST=F0 -DLAST=F1 -DFRAMES=N -DRADIUS_MM=r
include("${CMAKE_CURRENT_LIST_DIR}/require_defined.cmake")
pf_require_defined(viewer_obstacle_drag.cmake XVFB_RUN VIEWER CHECK OUT SIZE SCENES SCENE OBSTACLE DX DY FIRST LAST FRAMES RADIUS_MM)
file(REMOVE "${OUT}")
set(ENV{PF_SCENES_DIR} "${SCENES}")
execute_process(
  COMMAND "${XVFB_RUN}" -a -s "-screen 0 1280x720x24"
          "${VIEWER}" --scene ${SCENE} --size ${SIZE} --frames ${FRAMES} --screenshot "${OUT}"
          --drag-obstacle ${OBSTACLE},${DX},${DY},${FIRST},${LAST}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "pf_viewer output:\n${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pf_viewer under xvfb-run failed (${rc}):\n${err}")
endif()
if(err MATCHES "[Ee]rror")
  message(FATAL_ERROR "pf_viewer reported an error:\n${err}")
endif()
execute_process(COMMAND "${CHECK}" "${OUT}" ${SIZE} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the viewer's screenshot ${OUT} failed the check")
endif()

# "obstacle 0: start .. final .. velocity VX VY VZ  moved M m  window AX,AY -> BX,BY  view depth DA -> DB m"
set(num "-?[0-9]+\\.[0-9]+")
string(REGEX MATCHALL "obstacle [0-9]+: [^\n]*" lines "${out}")
list(LENGTH lines count)
if(count EQUAL 0)
  message(FATAL_ERROR "pf_viewer printed no obstacles")
endif()
set(found FALSE)
foreach(line IN LISTS lines)
  if(NOT line MATCHES "^obstacle ([0-9]+): .* velocity (${num}) (${num}) (${num})  moved (${num}) m")
    message(FATAL_ERROR "unexpected line: ${line}")
  endif()
  set(index ${CMAKE_MATCH_1})
  set(velocity "${CMAKE_MATCH_2} ${CMAKE_MATCH_3} ${CMAKE_MATCH_4}")
  set(moved ${CMAKE_MATCH_5})
  if(NOT index EQUAL OBSTACLE)
    if(NOT moved STREQUAL "0.0000")
      message(FATAL_ERROR "obstacle ${index} moved ${moved} m, only ${OBSTACLE} was dragged: ${line}")
    endif()
    continue()
  endif()
  set(found TRUE)
  if(NOT velocity MATCHES "^-?0\\.0000 -?0\\.0000 -?0\\.0000$")
    message(FATAL_ERROR "obstacle ${index} still moves after the release (velocity ${velocity}): ${line}")
  endif()
  if(moved MATCHES "^0\\.00")
    message(FATAL_ERROR "obstacle ${index} moved only ${moved} m: ${line}")
  endif()
  if(NOT line MATCHES "window (-?[0-9]+),(-?[0-9]+) -> (-?[0-9]+),(-?[0-9]+)  view depth ${num} -> ([0-9]+)\\.([0-9][0-9][0-9]) m")
    message(FATAL_ERROR "obstacle ${index} is not on screen: ${line}")
  endif()
  math(EXPR dx_seen "${CMAKE_MATCH_3} - ${CMAKE_MATCH_1}")
  math(EXPR dy_seen "${CMAKE_MATCH_4} - ${CMAKE_MATCH_2}")
  math(EXPR depth_mm "${CMAKE_MATCH_5} * 1000 + ${CMAKE_MATCH_6}")
  set(adx ${DX})
  set(ady ${DY})
  string(REGEX REPLACE "^-" "" adx "${adx}")
  string(REGEX REPLACE "^-" "" ady "${ady}")
  # ceil((|DX| + |DY|) * RADIUS / D) + 1
  math(EXPR tolerance "((${adx} + ${ady}) * ${RADIUS_MM} + ${depth_mm} - 1) / ${depth_mm} + 1")
  math(EXPR ex "${dx_seen} - (${DX})")
  math(EXPR ey "${dy_seen} - (${DY})")
  string(REGEX REPLACE "^-" "" ex "${ex}")
  string(REGEX REPLACE "^-" "" ey "${ey}")
  message(STATUS "obstacle ${index}: moved ${dx_seen},${dy_seen} px for a drag of ${DX},${DY} px "
                 "(off by ${ex},${ey}; tolerance ${tolerance} px), ${moved} m")
  if(ex GREATER tolerance OR ey GREATER tolerance)
    message(FATAL_ERROR "obstacle ${index} did not follow the cursor: moved ${dx_seen},${dy_seen} px on screen "
                        "for a drag of ${DX},${DY} px (tolerance ${tolerance} px)")
  endif()
endforeach()
if(NOT found)
  message(FATAL_ERROR "pf_viewer printed nothing about obstacle ${OBSTACLE}")
endif()
