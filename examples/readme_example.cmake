# The test readme_example: the README's C++ code block must be EXAMPLE's
# code from its first #include on, so that the README shows a program the
# tests build and run.
#   cmake -DREADME=... -DEXAMPLE=... -P readme_example.cmake
file(READ ${README} readme)
file(READ ${EXAMPLE} example)
string(FIND "${readme}" "```cpp\n" begin)
if(begin EQUAL -1)
  message(FATAL_ERROR "${README} has no ```cpp block")
endif()
math(EXPR begin "${begin} + 7")
string(SUBSTRING "${readme}" ${begin} -1 rest)
string(FIND "${rest}" "```" end)
string(SUBSTRING "${rest}" 0 ${end} shown)
string(FIND "${example}" "#include" first)
string(SUBSTRING "${example}" ${first} -1 code)
if(NOT shown STREQUAL code)
  message(FATAL_ERROR "${README}'s C++ example differs from ${EXAMPLE} (from its first #include): "
                      "copy the program into the README")
endif()
