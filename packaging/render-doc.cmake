# Renders one page of docs/ to HTML for the documentation folder the program ships:
#   cmake -DCMARK=cmark-gfm -DIN=docs/user-guide.md -DOUT=.../user-guide.html -P render-doc.cmake
# Links between the pages (user-guide.md -> cli.md) point at the rendered pages; pictures keep
# their relative paths (screenshots/ is installed beside the pages).
execute_process(COMMAND ${CMARK} --extension table --extension autolink --to html ${IN}
                OUTPUT_VARIABLE body RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "${CMARK} could not render ${IN}")
endif()
# Two passes: CMake refuses a replacement naming a group that did not take part in the match
# (a link without an anchor).
string(REGEX REPLACE "href=\"([A-Za-z0-9_-]+)\\.md#" "href=\"\\1.html#" body "${body}")
string(REGEX REPLACE "href=\"([A-Za-z0-9_-]+)\\.md\"" "href=\"\\1.html\"" body "${body}")
file(STRINGS ${IN} first LIMIT_COUNT 1)
string(REGEX REPLACE "^#+ *" "" title "${first}")
file(WRITE ${OUT} "<!DOCTYPE html>
<html lang=\"en\">
<head>
<meta charset=\"utf-8\">
<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">
<title>${title}</title>
<style>
body { font-family: sans-serif; max-width: 60em; margin: 1em auto; padding: 0 1em; line-height: 1.45; }
code, pre { font-family: monospace; background: #f2f4f6; }
pre { padding: 0.5em; overflow-x: auto; }
table { border-collapse: collapse; }
th, td { border: 1px solid #c8cdd2; padding: 0.2em 0.5em; vertical-align: top; }
img { max-width: 100%; }
</style>
</head>
<body>
${body}</body>
</html>
")
