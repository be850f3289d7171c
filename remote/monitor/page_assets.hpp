#pragma once
// The live page's files (remote/monitor/page/) and the machines' diagrams (docs/machines/*.svg),
// compiled into ringlet-monitor by embed_assets.cmake: the page loads nothing from anywhere else
// and works offline.
#include <cstddef>
#include <span>
#include <string_view>

namespace ringlet::monitor {

struct PageAsset {
  std::string_view path;  // URL path, e.g. "/app.js", "/machines/safety.svg"
  std::string_view mime;
  std::string_view bytes;
};

std::span<const PageAsset> page_assets() noexcept;

}  // namespace ringlet::monitor
