#pragma once
// One thread that owns an OpenGL context and does all the GL work of one
// Python object. A GL context is current on one thread at a time, and
// Python may call an object from any of its threads (with the GIL released
// while the GPU works): each call is posted here and waited for, so the
// context never changes threads and two calls never overlap.
//
// A task may take the GIL (a progress callback) only while its caller waits
// in run(), which releases it: owners wait for their last task (the GL
// objects' destruction) holding it, and no call can be running then (the
// call holds a reference to its owner).
#include <pybind11/pybind11.h>
#include <unistd.h>

#include <condition_variable>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <queue>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <utility>

namespace stochtex::python {

class GlThread {
public:
    GlThread() : owner_(getpid()), worker_([this] { loop(); }) {}
    ~GlThread() {
        {
            std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_one();
        worker_.join();
    }
    GlThread(const GlThread&) = delete;
    GlThread& operator=(const GlThread&) = delete;

    // Runs f on the GL thread and returns its result (or rethrows its
    // exception); the caller's GIL is released while it waits.
    template <class F>
    std::invoke_result_t<F> run(F&& f) {
        auto result = post(std::forward<F>(f));
        pybind11::gil_scoped_release release;
        return result.get();
    }
    // The same, waiting with the GIL held: for destructors, which may run
    // while the interpreter shuts down, where releasing and taking the GIL
    // back can end the calling thread mid-destructor.
    template <class F>
    std::invoke_result_t<F> runHoldingGil(F&& f) {
        return post(std::forward<F>(f)).get();
    }

    // False in a child of fork(): the worker thread stayed in the parent, so
    // nothing may be posted, and the owner must leak its GL objects and this.
    bool usable() const { return getpid() == owner_; }

private:
    template <class F>
    std::future<std::invoke_result_t<F>> post(F&& f) {
        if (!usable())
            throw std::runtime_error("this GPU object was made before a fork(); make a new one in this process");
        // Shared: the waiting caller may drop its future as soon as the
        // result is set, while the worker is still inside the task.
        auto task = std::make_shared<std::packaged_task<std::invoke_result_t<F>()>>(std::forward<F>(f));
        auto result = task->get_future();
        {
            std::lock_guard lock(mutex_);
            tasks_.push([task] { (*task)(); });
        }
        wake_.notify_one();
        return result;
    }

    void loop() {
        for (;;) {
            std::function<void()> task;
            {
                std::unique_lock lock(mutex_);
                wake_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
                if (tasks_.empty()) return;  // stopping, nothing left
                task = std::move(tasks_.front());
                tasks_.pop();
            }
            task();
        }
    }

    const pid_t owner_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::queue<std::function<void()>> tasks_;
    bool stopping_ = false;
    std::thread worker_;  // last: started once the members it uses exist
};

// Destroys an owner's GL objects on its thread; in a child of fork() leaks
// them and the thread instead (their context and thread are the parent's).
template <class... Owned>
void releaseOnGlThread(std::unique_ptr<GlThread>& gl, Owned&... owned) {
    if (!gl) return;
    if (!gl->usable()) {
        (static_cast<void>(owned.release()), ...);
        static_cast<void>(gl.release());
        return;
    }
    gl->runHoldingGil([&] { (owned.reset(), ...); });
}

}  // namespace stochtex::python
