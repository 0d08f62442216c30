# hsmu_set_warnings(target): warnings as a target property, never a global flag.
function(hsmu_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
endfunction()
