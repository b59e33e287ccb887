# Sets a lesson's docs page (pandoc's HTML fragment) into the lesson page's template.
# cmake -DTEMPLATE=lesson.html -DFRAGMENT=NN.fragment.html -DOUT=NN.html -DID=NN-name -DTITLE=...
#       [-DPREVIOUS=id -DPREVIOUS_TITLE=...] [-DNEXT=id -DNEXT_TITLE=...] -P page.cmake
file(READ ${FRAGMENT} DOCS)
# Links between the course's pages go to their pages in the site.
string(REGEX REPLACE "href=\"([0-9][0-9]-[a-z0-9-]+)\\.md" "href=\"\\1.html" DOCS "${DOCS}")
set(PREVIOUS_LINK "<span></span>")
set(NEXT_LINK "<span></span>")
if(PREVIOUS)
  set(PREVIOUS_LINK "<a id=\"previous\" href=\"${PREVIOUS}.html\">&larr; ${PREVIOUS_TITLE}</a>")
endif()
if(NEXT)
  set(NEXT_LINK "<a id=\"next\" href=\"${NEXT}.html\">${NEXT_TITLE} &rarr;</a>")
endif()
configure_file(${TEMPLATE} ${OUT} @ONLY)
