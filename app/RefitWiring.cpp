// The re-fit of changed meshes (issue 20 item 5) off the GUI thread: the
// session prepares a job (copies of what it reads), a worker thread runs the
// transfer and inpainting while the window stays responsive (progress in the
// status bar), and the result is applied on this thread as one undo step,
// unless the guide changed meanwhile: a stale result is discarded and the
// re-fit prepared again from the guide as it is now.
#include "MainWindow.h"

#include <QLabel>
#include <QStatusBar>
#include <QThread>
#include <QTimer>

#include <atomic>

namespace rs::app {

struct MainWindow::RefitRun {
    session::RefitJob job;
    std::optional<session::RefitJob> next; // asked for while this one ran: runs after it
    std::atomic<bool> cancel{false};
    std::atomic<double> fraction{0.0};
    Status result;
    QThread* thread = nullptr;
    QTimer* poll = nullptr;
    QLabel* label = nullptr; // in the status bar while it runs
    ~RefitRun()
    {
        cancel = true;
        if (thread) {
            thread->wait();
            delete thread;
        }
        delete poll;
        delete label;
    }
};

void MainWindow::startRefit(session::RefitJob job)
{
    if (m_refit) { // the running one reads an older guide: stop it, run this one next
        m_refit->next = std::move(job);
        m_refit->cancel = true;
        return;
    }
    auto run = std::make_shared<RefitRun>();
    run->job = std::move(job);
    RefitRun* raw = run.get();
    run->job.options.progress = [raw, inner = run->job.options.progress](double fraction) {
        raw->fraction = fraction;
        if (inner && !inner(fraction)) // the session's re-fit options may watch it too
            return false;
        return !raw->cancel.load();
    };
    m_refit = run;
    const std::size_t meshes = run->job.items.size();
    run->label = new QLabel;
    run->label->setObjectName("refitProgress");
    statusBar()->addPermanentWidget(run->label);
    auto showProgress = [this, meshes] {
        if (m_refit)
            m_refit->label->setText(tr("Re-fitting the weights of %n changed mesh(es): %1%", nullptr, int(meshes))
                                        .arg(int(m_refit->fraction.load() * 100.0)));
    };
    showProgress();
    run->poll = new QTimer;
    connect(run->poll, &QTimer::timeout, this, showProgress);
    run->poll->start(100);
    run->thread = QThread::create([raw] { raw->result = raw->job.run(); });
    run->thread->setObjectName("rigsmith-refit");
    connect(run->thread, &QThread::finished, this, &MainWindow::finishRefit, Qt::QueuedConnection);
    run->thread->start(QThread::LowPriority);
}

void MainWindow::finishRefit()
{
    if (!m_refit)
        return;
    std::shared_ptr<RefitRun> run = std::move(m_refit);
    run->thread->wait();
    run->poll->stop();
    run->label->hide();
    if (run->next) { // a newer guide asked for its own re-fit
        startRefit(std::move(*run->next));
        return;
    }
    if (run->result.failed())
        return; // cancelled: nothing changed
    if (!m_session.isCurrent(run->job)) { // edited meanwhile: never applied over newer edits
        statusBar()->showMessage(tr("The guide changed while its meshes were re-fitted: re-fitting again"), 5000);
        m_session.refitChangedMeshes(); // prepares from the guide as it is now (nothing, when nothing is left to re-fit)
        return;
    }
    std::vector<std::pair<std::size_t, std::vector<session::VertexRoute>>> routes; // the steps each vertex took
    const auto& meshes = m_session.characterMeshes();
    for (std::size_t i = 0; i < run->job.items.size(); ++i)
        for (std::size_t m = 0; m < meshes.size(); ++m)
            if (&meshes[m].data(m_session.models()) == run->job.items[i].mesh)
                routes.emplace_back(m, run->job.routes(i));
    auto applied = m_session.applyRefit(std::move(run->job)); // its notes go to the log
    if (applied)
        for (auto& [mesh, steps] : routes)
            setRoutes(mesh, std::move(steps));
    refreshScene();
    if (applied && !applied->empty())
        statusBar()->showMessage(tr("Re-fitted the weights of %n mesh(es) (Edit > Undo brings the previous ones back)", nullptr,
                                    int(applied->size())),
                                 8000);
}

} // namespace rs::app
