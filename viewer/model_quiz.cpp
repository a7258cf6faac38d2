// The Model's quiz session (model.h, flood/teach/quiz.h): kept apart from model.cpp.
#include "model.h"

namespace flood::view {

void Model::startQuiz(QuizActions asked) {
    quiz_ = QuizSession(trace_->events, asked);
    quizFor_ = generation_;
    quizOn_ = true;
}

const QuizSession& Model::quiz() const {
    // Another trace (an open, an edit, a turn of the dial): the same questions asked anew.
    if (quizFor_ != generation_) {
        quiz_ = QuizSession(trace_->events, quiz_.asked());
        quizFor_ = generation_;
    }
    return quiz_;
}

int Model::pendingQuestion() const {
    if (!quizOn_ || step_ >= steps()) return -1;
    const int q = quiz().questionOf(step_);  // events[step_] is the next event
    return q >= 0 && !quiz_.answered(size_t(q)) ? q : -1;
}

bool Model::answerQuiz(Action choice) {
    const int q = pendingQuestion();
    if (q < 0 || !quiz_.answer(size_t(q), choice)) return false;
    setPlaying(false);
    seek(step_ + 1);
    return true;
}

int Model::revealedQuestion() const {
    if (!quizOn_ || step_ == 0) return -1;
    const int q = quiz().questionOf(step_ - 1);
    return q >= 0 && quiz_.answered(size_t(q)) ? q : -1;
}

}  // namespace flood::view
