# The test example_dda_run: `dda run SCENE --out OUT`, then
# `python3 figures/plot_run.py OUT` (it writes OUT/run.png); fails if either
# fails or the files the README names are missing.
#   cmake -DDDA=... -DSCENE=... -DOUT=... -DPYTHON=... -DPLOT=... -P dda_run.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${DDA} run ${SCENE} --out ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "dda run ${SCENE} --out ${OUT}: exit status ${rc}")
endif()
foreach(f timeseries.csv snapshots.csv run.json)
  if(NOT EXISTS ${OUT}/${f})
    message(FATAL_ERROR "dda run wrote no ${OUT}/${f}")
  endif()
endforeach()
if(NOT PYTHON)
  message(FATAL_ERROR "python3 not found: cannot run ${PLOT}")
endif()
execute_process(COMMAND ${PYTHON} ${PLOT} ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/run.png)
  message(FATAL_ERROR "${PLOT} ${OUT}: exit status ${rc}, or no ${OUT}/run.png")
endif()
