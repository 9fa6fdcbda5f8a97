#include "sbsim/app/inputs/BundledScenario.h"

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {
constexpr const char* kName = "grid-rain";
}

BundledScenario BundledScenario::locate() {
    std::vector<fs::path> roots;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path prefix = exe.parent_path().parent_path();
        roots.push_back(prefix / SBSIM_SITE_PACKAGES / "sbsim" / "share" / "stories");  // pip install
        roots.push_back(prefix / "share" / "sbsim" / "stories");                        // cmake --install
    }
    roots.emplace_back(fs::path(SBSIM_SOURCE_DIR) / "stories");

    std::vector<std::string> searched;
    for (const fs::path& root : roots) {
        const fs::path dir = root / kName;
        const fs::path cfg = dir / (std::string(kName) + ".sumocfg");
        if (fs::is_regular_file(cfg)) {
            BundledScenario s{cfg, std::nullopt};
            if (fs::is_regular_file(dir / "story.py")) s.story = dir / "story.py";
            return s;
        }
        searched.push_back(cfg.string());
    }
    throw std::runtime_error(
        fmt::format("bundled scenario not found (looked for {}); pass --sumocfg FILE", fmt::join(searched, ", ")));
}

}  // namespace sbsim::app
