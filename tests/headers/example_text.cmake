# What the example extractors share (included by extract_example.cmake, extract_readme_example.cmake
# and extract_fragment.cmake).

# read_lines(PATH VAR): the file's lines as a list in VAR, each of its semicolons written @SEMICOLON@
# so that an example's own semicolons do not split a line.
function(read_lines path var)
  file(READ "${path}" text)
  string(REPLACE ";" "@SEMICOLON@" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(${var} "${lines}" PARENT_SCOPE)
endfunction()

# write_example(OUT TEXT): TEXT, its semicolons put back, written to OUT only when it changes, so
# that an unchanged example is not compiled again.
function(write_example out text)
  string(REPLACE "@SEMICOLON@" ";" text "${text}")
  file(WRITE "${out}.new" "${text}")
  file(COPY_FILE "${out}.new" "${out}" ONLY_IF_DIFFERENT)
  file(REMOVE "${out}.new")
endfunction()
