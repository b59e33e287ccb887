-- pandoc filter for a lesson's docs page in the browser's site (common/web/web.cmake): the page's
-- "In the window" section lists the window's keys, which do nothing on the page; a line under its
-- heading says which of the page's controls does the same.
function Pandoc(doc)
  local blocks = pandoc.List()
  for _, block in ipairs(doc.blocks) do
    blocks:insert(block)
    if block.t == "Header" and block.level == 2 and pandoc.utils.stringify(block.content) == "In the window" then
      blocks:insert(pandoc.Para({pandoc.Emph(pandoc.Inlines(
        "On this page the keys below do nothing: the controls beside the picture do what they do " ..
        "(the variant list, each option's box, the view, the pass stepper, the time and play/pause); " ..
        "drag the picture to orbit, turn the wheel to zoom."))}))
    end
  end
  doc.blocks = blocks
  return doc
end
