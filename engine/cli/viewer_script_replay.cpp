#include "cli/viewer_script_replay.h"

#include <stdexcept>
#include <utility>

namespace bounce {

namespace {

using Kind = ScriptCommand::Kind;

// Captures, frame counts and waits run after a frame is drawn; every other command before.
bool setsState(const ScriptCommand& c) {
  return c.kind != Kind::Frames && c.kind != Kind::Capture && c.kind != Kind::Window &&
         c.kind != Kind::WaitBake;
}

}  // namespace

ScriptReplay::ScriptReplay(std::string file, std::vector<ScriptCommand> commands)
    : file_(std::move(file)), commands_(std::move(commands)) {}

void ScriptReplay::run(const ScriptCommand& c, ScriptActions& viewer) {
  const auto slot = static_cast<std::size_t>(c.count - 1);
  switch (c.kind) {
    case Kind::Camera:
      viewer.selectCamera(c.text);
      break;
    case Kind::View:
      viewer.lookFrom(c.position, c.target);
      break;
    case Kind::Mode:
      viewer.setModeNamed(c.text);
      break;
    case Kind::Exposure:
      viewer.setExposure(c.number);
      break;
    case Kind::Panel:
      viewer.showPanel(c.on);
      break;
    case Kind::Rebake:
      viewer.startRebake();
      break;
    case Kind::CancelBake:
      viewer.cancelRebake();
      break;
    case Kind::Light:
      viewer.setLightField(c.text, c.field, c.value);
      break;
    case Kind::BookmarkSave:
      viewer.saveBookmark(slot);
      break;
    case Kind::BookmarkGo:
      viewer.goToBookmark(slot);
      break;
    case Kind::VplPaths:
      viewer.setVplPaths(static_cast<uint64_t>(c.count));
      break;
    case Kind::VplClamp:
      viewer.setVplClamp(c.number);
      break;
    case Kind::Reference:
      viewer.loadReference(c.text);
      break;
    case Kind::Compare:
      viewer.setComparison(c.text);
      break;
    case Kind::Frames:
    case Kind::Capture:
    case Kind::Window:
    case Kind::WaitBake:
      break;  // after a frame: afterFrame
  }
}

void ScriptReplay::beforeFrame(ScriptActions& viewer) {
  for (; next_ < commands_.size() && setsState(commands_[next_]); ++next_) {
    const ScriptCommand& c = commands_[next_];
    try {
      run(c, viewer);
    } catch (const std::exception& e) {
      throw std::runtime_error(file_ + ": line " + std::to_string(c.line) + ": " + e.what());
    }
  }
}

bool ScriptReplay::afterFrame(ScriptActions& viewer) {
  while (next_ < commands_.size() && !setsState(commands_[next_])) {
    const ScriptCommand& c = commands_[next_];
    if (c.kind == Kind::WaitBake) {
      // The next frame takes a finished pass and draws it; captures follow that frame.
      if (viewer.rebakePending()) return false;
      ++next_;
      continue;
    }
    if (c.kind == Kind::Frames) {
      if (++framesDrawn_ < c.count) return false;
      framesDrawn_ = 0;
      ++next_;
      return next_ == commands_.size();
    }
    if (c.kind == Kind::Capture) viewer.capture(c.text);
    if (c.kind == Kind::Window) viewer.captureWindow(c.text);
    ++next_;
  }
  return next_ == commands_.size();
}

}  // namespace bounce
