# cmake -DEXAMPLE=path -DSOURCE_DIR=... -DWORK_DIR=... -P run_example.cmake: runs talkface.hpp's
# example where it finds the files it names (a face, a transcript, its recording: samples/) and
# checks the page it writes: the face's SVG and the recording in one HTML file (the animation
# itself is packed; the browser tests look at it).
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
file(COPY_FILE "${SOURCE_DIR}/samples/faces/female.xml" "${WORK_DIR}/face.xml")
file(COPY_FILE "${SOURCE_DIR}/samples/speech/demo.txt" "${WORK_DIR}/speech.txt")
file(COPY_FILE "${SOURCE_DIR}/samples/speech/demo.ogg" "${WORK_DIR}/speech.ogg")
execute_process(COMMAND "${EXAMPLE}" WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE status
                OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the example failed (${status}): ${output}")
endif()
if(NOT output STREQUAL "")
  message(FATAL_ERROR "the example printed (the library prints nothing): ${output}")
endif()
file(READ "${WORK_DIR}/talk.html" page)
foreach(part "<svg" "data:audio/")
  string(FIND "${page}" "${part}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "talk.html has no ${part}")
  endif()
endforeach()
string(LENGTH "${page}" size)
message(STATUS "talk.html: ${size} bytes")
