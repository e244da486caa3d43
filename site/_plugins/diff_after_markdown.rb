# The diffs of "What changed in each part" are large blocks of generated HTML (one span per line and
# token). Passing them through kramdown would take seconds for nothing, so the page only leaves a
# placeholder, <!-- t10-diff D F --> (diff D of _data/diffs.json, file F), and this hook puts the
# HTML in after the Markdown conversion. build_site.py writes the HTML with Python's Pygments when
# it is installed; otherwise the diff text is coloured here with Rouge's diff lexer.
require "cgi"

Jekyll::Hooks.register :pages, :post_convert do |page|
  next unless page.content.include?("<!-- t10-diff ")

  diffs = page.site.data["diffs"]
  page.content = page.content.gsub(/<!-- t10-diff (\d+) (\d+) -->/) do
    entry = diffs.fetch(Regexp.last_match(1).to_i).fetch("files").fetch(Regexp.last_match(2).to_i)
    body = entry["html"].to_s
    if body.empty?
      body = Rouge::Formatters::HTML.new.format(Rouge::Lexers::Diff.new.lex(entry.fetch("diff")))
    end
    %(<div class="highlight diff"><pre class="highlight"><code>#{body}</code></pre></div>)
  end
end
