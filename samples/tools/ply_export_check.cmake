# CTest driver of pf_headless --export-ply: runs FRAMES frames of SCENE (a scene file) into
# OUT in FORMAT, then checks that frame_0000.ply (the fill) .. frame_<FRAMES>.ply and nothing
# else are there and that pf_ply_check (CHECK) accepts each: as many vertices as pf_headless
# reported particles, finite, inside the domain read from the scene file itself.
# Arguments: -DHEADLESS= -DCHECK= -DSCENE= -DOUT= -DFRAMES= -DFORMAT=binary|ascii
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${HEADLESS}" --scene "${SCENE}" --frames ${FRAMES} --every 0
                        --export-ply "${OUT}" --ply-format ${FORMAT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pf_headless failed (${rc}):\n${log}\n${err}")
endif()
if(NOT log MATCHES "=== [^\n]*: ${FRAMES} frames, ([0-9]+) particles")
  message(FATAL_ERROR "no particle count in pf_headless's report:\n${log}")
endif()
set(count "${CMAKE_MATCH_1}")
if(count EQUAL 0)
  message(FATAL_ERROR "the scene has no particles: nothing to check")
endif()

# The domain as the scene file gives it: cell size, cells per axis, origin.
file(READ "${SCENE}" json)
string(JSON cell GET "${json}" grid cell_size)
set(domain "${cell}")
foreach(axis 0 1 2)
  string(JSON n GET "${json}" grid size ${axis})
  list(APPEND domain "${n}")
endforeach()
foreach(axis 0 1 2)
  string(JSON o ERROR_VARIABLE no_origin GET "${json}" grid origin ${axis})
  if(no_origin)
    set(o 0)
  endif()
  list(APPEND domain "${o}")
endforeach()

file(GLOB files RELATIVE "${OUT}" "${OUT}/*")
list(LENGTH files nfiles)
math(EXPR expected "${FRAMES} + 1")
if(NOT nfiles EQUAL expected)
  message(FATAL_ERROR "${nfiles} files in ${OUT}, expected ${expected} (frames 0..${FRAMES}): ${files}")
endif()
foreach(f RANGE 0 ${FRAMES})
  string(LENGTH "000${f}" len)
  math(EXPR skip "${len} - 4")
  string(SUBSTRING "000${f}" ${skip} 4 num)
  execute_process(COMMAND "${CHECK}" "${OUT}/frame_${num}.ply" ${count} ${domain} COMMAND_ERROR_IS_FATAL ANY)
endforeach()
