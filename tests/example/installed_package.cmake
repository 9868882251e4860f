# The engine as another project uses it: install it into a fresh prefix, configure and build
# examples/ against the installed package (find_package(Lightprobe)), run the example program on its
# white furnace map (radiance 1 everywhere) and check the figures it prints against their exact values.
# Arguments (-D): BUILD_DIR (this project's build), EXAMPLES_DIR, WORK_DIR, CXX_COMPILER, CXX_LAUNCHER.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/run)

function(run_step)
  execute_process(COMMAND ${ARGV} WORKING_DIRECTORY ${WORK_DIR}/run RESULT_VARIABLE status
                  OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGV}\n${out}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

run_step(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
run_step(${CMAKE_COMMAND} -S ${EXAMPLES_DIR} -B ${WORK_DIR}/build -DCMAKE_BUILD_TYPE=Release
         -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
         -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
run_step(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run_step(${WORK_DIR}/build/lightprobe_tour)
message("${step_output}")

# The number after `label` in the program's output must lie in [low, high].
function(expect label low high)
  if(NOT step_output MATCHES "${label} (-?[0-9.]+)")
    message(FATAL_ERROR "no '${label}' in the output")
  endif()
  if(CMAKE_MATCH_1 LESS low OR CMAKE_MATCH_1 GREATER high)
    message(FATAL_ERROR "${label} ${CMAKE_MATCH_1} is outside [${low}, ${high}]")
  endif()
endfunction()

# 4 pi = 12.56637: the exact per-row solid angles sum to it up to float rounding.
expect("white_furnace.pfm: 64 x 32 pfm, power" 12.5650 12.5677)
# 4096 stratified samples of a constant map: within 0.5%.
expect("estimated power" 12.50 12.63)
# The 16 lights carry the map's power; median splits of a 64 x 32 grid give each 1/16 of it within 15%.
expect("16 lights, power" 12.5650 12.5677)
expect("energy min" 0.667 0.903)
expect("max" 0.667 0.903)
# The sphere of albedo 0.5 in a furnace of radiance 1: 0.5, here the mean of 16 pixels at 16 samples.
expect("centre radiance" 0.48 0.52)
if(NOT EXISTS ${WORK_DIR}/run/render.png)
  message(FATAL_ERROR "render.png was not written")
endif()
