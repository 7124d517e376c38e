# The Wine prefix every Windows test shares, and one persistent wineserver for
# the whole run: a server that exits while the next test connects to it fails
# that test ("recvmsg: Connection reset by peer"), so one is started before
# the prefix is made and stopped by the cleanup fixture.
#   cmake -DACTION=start|stop -DWINE=... -DWINESERVER=... -DPREFIX=... -P wine_server.cmake
set(ENV{WINEPREFIX} ${PREFIX})
set(ENV{WINEDEBUG} -all)
set(ENV{WINEDLLOVERRIDES} "mscoree,mshtml=")
if(ACTION STREQUAL "start")
  file(MAKE_DIRECTORY ${PREFIX})
  execute_process(COMMAND ${WINESERVER} -k OUTPUT_FILE /dev/null ERROR_FILE /dev/null)
  # The server keeps the output it inherits: not a pipe, or this would wait on it.
  execute_process(COMMAND ${WINESERVER} -p OUTPUT_FILE /dev/null ERROR_FILE /dev/null RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "wineserver -p failed (${rc})")
  endif()
  execute_process(COMMAND ${WINE} cmd /c exit 0 OUTPUT_FILE /dev/null ERROR_FILE /dev/null RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the Wine prefix ${PREFIX} could not be made (${rc})")
  endif()
else()
  execute_process(COMMAND ${WINESERVER} -k OUTPUT_FILE /dev/null ERROR_FILE /dev/null)
endif()
