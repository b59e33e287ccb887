-- pandoc filter for a lesson's docs page in the browser's site (common/web/web.cmake): a link to a
-- file of the repository (../lessons/NN-name/main.cpp, ../common/geometry/planar.h, scenes.md)
-- leads nowhere in the site, so it becomes its text with the file's path in the repository beside
-- it. Links to another lesson's page (NN-name.md, made NN-name.html by page.cmake), to a part of
-- the page (#...) and to other sites stay links.
function Link(link)
  local target = link.target
  if target:match("^%a[%w+.-]*:") or target:match("^#") or target:match("^%d%d%-[%w-]+%.md") then
    return nil
  end
  local path = target:gsub("#.*$", "")
  if path:sub(1, 3) == "../" then
    path = path:sub(4)
  else
    path = "docs/" .. path
  end
  local inlines = link.content
  local text = pandoc.utils.stringify(inlines)
  if text ~= path and text ~= path:gsub("/$", "") then
    inlines:insert(pandoc.Str(" ("))
    inlines:insert(pandoc.Code(path))
    inlines:insert(pandoc.Str(")"))
  end
  return pandoc.Span(inlines, {class = "repository-path", title = "in the repository: " .. path})
end
