# CTest driver: pf_headless draws the scene's obstacles. The first frame of the scene is rendered
# twice, with the obstacles drawn and with --hide-obstacles (simulated alike, left out of the
# picture); at each obstacle's projected centre, which pf_headless prints, the two images must
# differ. Removing the obstacle drawing makes the images equal there and fails the test.
#   -DHEADLESS=... -DCHECK=pf_png_check -DSCENE=path.json -DOUT=dir -DSIZE=WxH
include("${CMAKE_CURRENT_LIST_DIR}/require_defined.cmake")
pf_require_defined(headless_obstacles_drawn.cmake HEADLESS CHECK SCENE OUT SIZE)
file(REMOVE_RECURSE "${OUT}")

foreach(run drawn hidden)
  set(extra "")
  if(run STREQUAL "hidden")
    set(extra --hide-obstacles)
  endif()
  execute_process(
    COMMAND "${HEADLESS}" --scene "${SCENE}" --frames 0 --every 1 --size ${SIZE} --out "${OUT}/${run}" ${extra}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out_${run} ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pf_headless (${run}) failed (${rc}):\n${out_${run}}\n${err}")
  endif()
endforeach()

# "  obstacle 0 (sphere, drawn) centre at pixel 151.3,97.2"
string(REGEX MATCHALL "obstacle [0-9]+ \\([a-z]+, drawn\\) centre at pixel [0-9.]+,[0-9.]+" lines "${out_drawn}")
list(LENGTH lines count)
if(count EQUAL 0)
  message(FATAL_ERROR "pf_headless printed no obstacle on screen:\n${out_drawn}")
endif()
set(pixels "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE ".* at pixel " "" pixel "${line}")
  list(APPEND pixels "${pixel}")
endforeach()
message(STATUS "${count} obstacles, centres at ${pixels}")
execute_process(COMMAND "${CHECK}" --differs "${OUT}/drawn/frame_0000.png" "${OUT}/hidden/frame_0000.png" ${pixels}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the obstacles do not show in ${OUT}/drawn/frame_0000.png")
endif()
