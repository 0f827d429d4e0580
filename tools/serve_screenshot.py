#!/usr/bin/python3
"""docs/img/serve.png: tippe serve's page in headless Chromium (selenium), as README
shows it: the printed M12 setscrew at 40 % infill, a launch checked in group II.
Usage: /usr/bin/python3 tools/serve_screenshot.py BUILD/tippe [OUT.png]"""
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "tests"))
from serve_lib import Server, REPO  # noqa: E402

from selenium import webdriver  # noqa: E402
from selenium.webdriver.chrome.options import Options  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402
from selenium.webdriver.support.ui import WebDriverWait  # noqa: E402

tippe = sys.argv[1]
out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(REPO, "docs", "img", "serve.png")
opts = Options()
for arg in ["--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1200,1500",
            "--hide-scrollbars", "--force-device-scale-factor=1"]:
    opts.add_argument(arg)
opts.binary_location = "/usr/bin/chromium"
with Server(tippe) as srv:
    d = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)
    try:
        wait = WebDriverWait(d, 30)
        d.get(srv.url + "?design=m12-setscrew-printed")
        wait.until(lambda d: d.execute_script("return state.sweep !== null"))
        box = d.find_element(By.ID, "f-parts_0__print_infill")
        box.send_keys(Keys.CONTROL, "a")
        box.send_keys("0.4")
        # the build sheet's verdict, which arrives after the sweep
        wait.until(lambda d: d.execute_script("return state.verdict !== null"))
        time.sleep(0.5)
        d.execute_script("pointAt(9.5)")
        d.find_element(By.ID, "check").click()
        wait.until(lambda d: d.find_element(By.ID, "check-result").get_attribute("data-verdict"))
        time.sleep(0.5)
        d.execute_script("document.activeElement.blur(); window.scrollTo(0, 0)")
        d.save_screenshot(out)
    finally:
        d.quit()
print("wrote " + out)
