# CTest driver of pf_headless --export-vdb: runs FRAMES frames of SCENE (a scene file) with the
# PLY and the OpenVDB export on, checks that frames 0..FRAMES each have frame_NNNN.vdb and
# frame_NNNN_points.vdb and nothing else is there, and that pf_vdb_check (CHECK) accepts each
# against the same frame's PLY: the points file holds exactly the PLY's particles (positions and
# velocities), the volume file's liquid volume is the particles' implied volume within its
# tolerance and its velocities are the particles'.
# Arguments: -DHEADLESS= -DCHECK= -DSCENE= -DOUT= -DFRAMES=
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${HEADLESS}" --scene "${SCENE}" --frames ${FRAMES} --every 0
                        --export-ply "${OUT}/ply" --export-vdb "${OUT}/vdb"
                RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pf_headless failed (${rc}):\n${log}\n${err}")
endif()
if(NOT log MATCHES "export: ([0-9]+) frames")
  message(FATAL_ERROR "no export line in pf_headless's report:\n${log}")
endif()
file(READ "${SCENE}" json)
string(JSON cell GET "${json}" grid cell_size)

file(GLOB files RELATIVE "${OUT}/vdb" "${OUT}/vdb/*")
list(LENGTH files nfiles)
math(EXPR expected "2 * (${FRAMES} + 1)")
if(NOT nfiles EQUAL expected)
  message(FATAL_ERROR "${nfiles} files in ${OUT}/vdb, expected ${expected} (frames 0..${FRAMES}, two each): ${files}")
endif()
foreach(f RANGE 0 ${FRAMES})
  string(LENGTH "000${f}" len)
  math(EXPR skip "${len} - 4")
  string(SUBSTRING "000${f}" ${skip} 4 num)
  execute_process(COMMAND "${CHECK}" points "${OUT}/vdb/frame_${num}_points.vdb" --ply "${OUT}/ply/frame_${num}.ply"
                  COMMAND_ERROR_IS_FATAL ANY)
  execute_process(COMMAND "${CHECK}" volume "${OUT}/vdb/frame_${num}.vdb" --cell ${cell}
                          --ply "${OUT}/ply/frame_${num}.ply" COMMAND_ERROR_IS_FATAL ANY)
endforeach()
