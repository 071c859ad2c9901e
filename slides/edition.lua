-- One edition of the lecture slides from the bilingual sources (pandoc -L slides/edition.lua).
--   -M lang=en|de     the language: keeps `::: en` / `::: de` blocks and `## ... {.en}` / `{.de}` headings
--                     of that language, drops the other's (slides/edition_text.sh does the same for the
--                     fast text checks); raw LaTeX chooses with \EnDe{english}{deutsch} (preamble.tex)
--   -M chapter=N      a deck: title "Chapter N: <its # heading>", and a last slide "References" with
--                     the sources the deck cites
--   -M course=true    the whole course: an overview slide first, the bibliography of every cited
--                     source last
--   -M clips=DIR      where the live-demo clips are, relative to the PDF (links run:clips/NAME)
-- A figure whose image has crop="L B R T" (pixels cut from the left, bottom, right, top) is set with
-- \includegraphics[trim=...,clip]: the renderer's PNGs carry no resolution, so pdfTeX reads 1 px as
-- 1 bp. width=P% is of the line (column), height=P% of the text height, as pandoc does it.
-- The sources come from slides/references.yaml (--metadata-file): a citation is [Key] in the text,
-- e.g. [Müller07]; a key without an entry stops the build (slides/check_refs.sh says so earlier).

local words = {
  en = { chapter = "Chapter", refs = "References", bib = "Bibliography", overview = "The ten chapters",
         title = "Cloth simulation (Stoffsimulation)",
         course_sub = "Mass-spring systems, mass-spring networks, Position Based Dynamics",
         institute = 'clothlab -- after "Advanced Game Physics -- Stoffsimulation" (FAU, WS 2015/16)' },
  de = { chapter = "Kapitel", refs = "Literatur", bib = "Literaturverzeichnis", overview = "Die zehn Kapitel",
         title = "Stoffsimulation",
         course_sub = "Masse-Feder-Systeme, Masse-Feder-Netzwerke, Position-Based-Dynamics",
         institute = 'clothlab -- nach "Advanced Game Physics -- Stoffsimulation" (FAU, WS 2015/16)' },
}
local KEY = "%[(%u[^%[%]%s]*%d%d%l?)%]"  -- [Waters87], [Müller07]: the same pattern as check_refs.sh

local function str(m) return m and pandoc.utils.stringify(m) or nil end

local function has_class(el, c)
  for _, x in ipairs(el.classes) do if x == c then return true end end
  return false
end

local function other_lang(el, lang)
  for _, l in ipairs({ "en", "de" }) do
    if l ~= lang and has_class(el, l) then return true end
  end
  return false
end

-- the entry of a source in this language (a plain entry, or one per language)
local function entry(sources, key, lang)
  local e = sources[key]
  if e == nil then return nil end
  if e.t == "MetaMap" or (type(e) == "table" and e.en) then e = e[lang] or e.en end
  if e.t == "MetaBlocks" then return pandoc.utils.blocks_to_inlines(e) end
  if e.t == "MetaInlines" then return e end
  return pandoc.Inlines(e)
end

local function size(v, of)
  local p = v and v:match("^([%d.]+)%%$")
  if p then return string.format("%.3f%s", tonumber(p) / 100, of) end
  return v
end

-- Para with one cropped image (pandoc 2.17: an implicit figure) -> \begin{figure} with trim and clip
local function cropped_figure(p)
  local img = p.content[1]
  if #p.content ~= 1 or img.t ~= "Image" or not img.attributes.crop then return nil end
  local opts = { "trim=" .. img.attributes.crop, "clip", "keepaspectratio" }
  if img.attributes.width then opts[#opts + 1] = "width=" .. size(img.attributes.width, "\\linewidth") end
  if img.attributes.height then opts[#opts + 1] = "height=" .. size(img.attributes.height, "\\textheight") end
  local caption = pandoc.write(pandoc.Pandoc({ pandoc.Plain(img.caption) }), "latex")
  return pandoc.RawBlock("latex", "\\begin{figure}\n\\centering\n\\includegraphics[" .. table.concat(opts, ",")
    .. "]{" .. img.src .. "}\n\\caption{" .. caption .. "}\n\\end{figure}")
end

local function cited_keys(doc)
  local seen, keys = {}, {}
  local function scan(s)
    for k in s:gmatch(KEY) do
      if not seen[k] then seen[k] = true; keys[#keys + 1] = k end
    end
  end
  pandoc.Pandoc(doc.blocks):walk({ Str = function(s) scan(s.text) end,  -- the slides, not the metadata
    RawInline = function(r) scan(r.text) end, RawBlock = function(r) scan(r.text) end })
  table.sort(keys)
  return keys
end

local function reference_slide(title, keys, sources, lang)
  local items = {}
  for _, k in ipairs(keys) do
    local e = entry(sources, k, lang)
    if e == nil then error("slides: [" .. k .. "] is cited but has no entry in slides/references.yaml") end
    local item = pandoc.Inlines({ pandoc.Strong({ pandoc.Str("[" .. k .. "]") }), pandoc.Space() })
    item:extend(e)
    items[#items + 1] = { pandoc.Plain(item) }
  end
  return { pandoc.Header(2, pandoc.Inlines({ pandoc.Str(title) }), pandoc.Attr("", { "allowframebreaks" })),
           pandoc.BulletList(items) }
end

function Pandoc(doc)
  local lang = str(doc.meta.lang) or "en"
  local w = words[lang] or error("slides: lang must be en or de, not " .. lang)
  local clips = str(doc.meta.clips)
  doc = doc:walk({
    Div = function(d)
      if other_lang(d, lang) then return {} end
      if has_class(d, lang) then return d.content end
    end,
    Header = function(h)
      if other_lang(h, lang) then return {} end
    end,
    Para = cropped_figure,
    Link = function(l)
      if clips and l.target:match("^run:clips/") then l.target = "run:" .. clips .. l.target:sub(10) end
      return l
    end,
  })
  local sources = doc.meta.sources or {}
  local keys = cited_keys(doc)
  doc.meta.institute = w.institute
  if doc.meta.course then
    local items = {}
    for _, b in ipairs(doc.blocks) do
      if b.t == "Header" and b.level == 1 then items[#items + 1] = { pandoc.Plain(b.content) } end
    end
    local head = { pandoc.Header(2, pandoc.Inlines({ pandoc.Str(w.overview) })), pandoc.OrderedList(items) }
    doc.blocks = pandoc.List(head) .. doc.blocks
    doc.blocks:extend(reference_slide(w.bib, keys, sources, lang))
    doc.meta.title = w.title
    doc.meta.subtitle = w.course_sub
  else
    local n = str(doc.meta.chapter)
    local h1
    for _, b in ipairs(doc.blocks) do
      if b.t == "Header" and b.level == 1 then h1 = b; break end
    end
    if n and h1 then
      local t = pandoc.Inlines({ pandoc.Str(w.chapter .. " " .. n .. ":"), pandoc.Space() })
      t:extend(h1.content)
      doc.meta.title = t
      doc.meta.subtitle = w.title
    end
    if #keys == 0 then error("slides: the deck cites no source ([Key] from slides/references.yaml)") end
    doc.blocks:extend(reference_slide(w.refs, keys, sources, lang))
  end
  return doc
end
