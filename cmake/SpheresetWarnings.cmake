# Warning flags applied per target (house rule: -Wall -Wextra -Wshadow on every target).
function(sphereset_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow)
endfunction()
