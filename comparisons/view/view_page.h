#pragma once
/// A 3-D view page, written beside the files it shows: DIR/NAME.html, DIR/NAME.data.js and the
/// viewer's files (viewer_assets.h). The data file is one classic script,
/// `window.TECIDO_VIEW = {...};` (JSON, ASCII only: every other character as \uXXXX), which the
/// page loads before tecido-viewer.js: a page opened from disk may not fetch a file (Chromium
/// refuses fetch and XHR from file://) but may run its own scripts. `data["kind"]` picks the view
/// (web/src/main.js): "run", "tritri", "plane", "ccd". The page's title is text
/// (view/html_text.h); the data's strings are shown by the viewer as text (textContent), never as HTML.
#include "comparisons/io/json_reader.h"

#include <string>

namespace tecido::view {

/// Writes the page. Returns the page's file name ("NAME.html"). Throws io::OutputError when a file
/// cannot be written.
std::string write_view_page(const std::string& dir, const std::string& name, const std::string& title,
                            const io::Json& data);

/// The page's HTML (no file written).
std::string view_page_html(const std::string& name, const std::string& title);

}  // namespace tecido::view
