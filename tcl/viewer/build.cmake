# SPDX-License-Identifier: MIT
# Build step of the viewer page, run by CMake at build time:
#   npm ci (only when package-lock.json changed) in BIN/npm, esbuild SRC/src/main.js into one
#   minified script, then embed.cmake writes OUTPUT (C++).
# If npm ci or esbuild fails (e.g. the npm registry is unreachable), a warning is printed and the
# fallback page is embedded instead, so the rest of dabs still builds.
# Usage: cmake -DNODE=.. -DNPM=.. -DSRC=<tcl/viewer> -DBIN=<build dir> -DOUTPUT=.. -P build.cmake
set(npm_dir "${BIN}/npm")
set(stamp "${npm_dir}/node_modules/.dabs-installed")
file(MAKE_DIRECTORY "${npm_dir}")
set(ok TRUE)
set(reason "")
set(need_install TRUE)
if(EXISTS "${stamp}" AND EXISTS "${npm_dir}/package-lock.json")
  file(SHA256 "${SRC}/package-lock.json" want)
  file(SHA256 "${npm_dir}/package-lock.json" have)
  if(want STREQUAL have)
    set(need_install FALSE)
  endif()
endif()
if(need_install)
  file(REMOVE "${stamp}")
  file(COPY "${SRC}/package.json" "${SRC}/package-lock.json" DESTINATION "${npm_dir}")
  # --ignore-scripts: no package runs code at install (esbuild finds its platform binary without
  # its postinstall step).
  execute_process(COMMAND "${NPM}" ci --ignore-scripts --no-audit --no-fund --loglevel=error
                  WORKING_DIRECTORY "${npm_dir}" RESULT_VARIABLE rc)
  if(rc EQUAL 0)
    file(TOUCH "${stamp}")
  else()
    set(ok FALSE)
    set(reason "npm ci failed (${rc})")
  endif()
endif()
if(ok)
  # The sources live outside npm_dir, so imports are resolved through NODE_PATH.
  execute_process(COMMAND "${CMAKE_COMMAND}" -E env "NODE_PATH=${npm_dir}/node_modules"
                  "${NODE}" "${npm_dir}/node_modules/esbuild/bin/esbuild"
                  "${SRC}/src/main.js" --bundle --minify --format=iife --target=es2020
                  --legal-comments=none --log-level=warning "--outfile=${BIN}/bundle.js"
                  WORKING_DIRECTORY "${npm_dir}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    set(ok FALSE)
    set(reason "esbuild failed (${rc})")
  endif()
endif()
if(ok)
  set(TEMPLATE "${SRC}/page.html")
  set(JS "${BIN}/bundle.js")
  set(CSS "${BIN}/bundle.css")
  set(BUILT 1)
else()
  message(WARNING "viewer: ${reason}; `recorder Viewer` writes a page without the viewer")
  set(TEMPLATE "${SRC}/fallback.html")
  set(JS "")
  set(BUILT 0)
endif()
include("${SRC}/embed.cmake")
