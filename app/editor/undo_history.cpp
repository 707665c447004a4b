#include "undo_history.h"

namespace patina::editor {

void UndoHistory::record(EditSnapshot before) {
    undo_.push_back(std::move(before));
    if (undo_.size() > limit_) {
        undo_.pop_front();
    }
    redo_.clear();
}

std::optional<EditSnapshot> UndoHistory::undo(EditSnapshot current) {
    if (undo_.empty()) {
        return std::nullopt;
    }
    EditSnapshot previous = std::move(undo_.back());
    undo_.pop_back();
    redo_.push_back(std::move(current));
    return previous;
}

std::optional<EditSnapshot> UndoHistory::redo(EditSnapshot current) {
    if (redo_.empty()) {
        return std::nullopt;
    }
    EditSnapshot next = std::move(redo_.back());
    redo_.pop_back();
    undo_.push_back(std::move(current));
    return next;
}

}  // namespace patina::editor
