#include "viewer/ViewerState.h"

namespace dermis::viewer {

void ViewerState::setAov(Aov newAov, float cameraDistanceM) {
    aov = newAov;
    aovMapping = defaultAovMapping(newAov, cameraDistanceM);
}

void ViewerState::report(std::string text, bool isError) {
    message = std::move(text);
    messageIsError = isError;
    messageTime = std::chrono::steady_clock::now();
}

}  // namespace dermis::viewer
