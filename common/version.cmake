# Writes the version header OUT from its template IN, at build time (the target gg_version runs it on
# every build): the git commit of the sources in SRC, with "-dirty" when a tracked file differs from
# it, so that --version and every output's provenance name the code as it was built, not as it was
# when cmake last ran. configure_file rewrites OUT only when that changes (no needless rebuilds).
execute_process(COMMAND git rev-parse --short=12 HEAD
                WORKING_DIRECTORY ${SRC}
                OUTPUT_VARIABLE GG_GIT_HASH OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(NOT GG_GIT_HASH)
  set(GG_GIT_HASH "unknown")
else()
  execute_process(COMMAND git status --porcelain --untracked-files=no
                  WORKING_DIRECTORY ${SRC}
                  OUTPUT_VARIABLE GG_CHANGES OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET)
  if(GG_CHANGES)
    string(APPEND GG_GIT_HASH "-dirty")
  endif()
endif()
configure_file(${IN} ${OUT} @ONLY)
